#include "App/Gui/ImageView.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <GL/gl.h>
#include <imgui.h>

namespace rt::gui
{
GlTexture::GlTexture() { glGenTextures(1, &m_id); }

GlTexture::~GlTexture() { glDeleteTextures(1, &m_id); }

void GlTexture::upload(int width, int height, const unsigned char* rgba)
{
    glBindTexture(GL_TEXTURE_2D, m_id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    if (width != m_width || height != m_height)
    {
        // Nearest when magnified: a 64-pixel test render should look like 64 pixels, not a blur.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        m_width = width;
        m_height = height;
    }
    else
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void ImageView::update(const std::shared_ptr<const Preview>& preview, bool heatmap)
{
    const bool showHeatmap = heatmap && preview && !preview->costRgba.empty();
    if (!preview || (preview->generation == m_generation && showHeatmap == m_showsHeatmap))
        return;
    m_generation = preview->generation;
    m_showsHeatmap = showHeatmap;
    const Image& shownImage = showHeatmap ? preview->costPainted : preview->linear;
    const std::vector<unsigned char>& rgba = showHeatmap ? preview->costRgba : preview->rgba;
    m_width = shownImage.width();
    m_height = shownImage.height();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const int step = (std::max(m_width, m_height) + maxSize - 1) / std::max(maxSize, 1);
    if (step <= 1)
    {
        m_texture.upload(m_width, m_height, rgba.data());
        return;
    }
    // Wider than a texture may be (renders go to 65536 pixels): show every step-th pixel; Save image keeps all.
    const int w = m_width / step;
    const int h = m_height / step;
    std::vector<unsigned char> shown(std::size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            std::copy_n(rgba.data() + (std::size_t(y * step) * m_width + std::size_t(x * step)) * 4, 4,
                        shown.data() + (std::size_t(y) * w + x) * 4);
    m_texture.upload(w, h, shown.data());
}

ImagePointer ImageView::draw(bool dim, const std::string& overlay)
{
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 region = ImGui::GetContentRegionAvail();
    if (region.x < 1.0f || region.y < 1.0f)
        return {};
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    // A neutral backdrop a shade off the pane's, in either theme: no tint next to the image's colours.
    const ImVec4 pane = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    const ImVec4 ink = ImGui::GetStyleColorVec4(ImGuiCol_Text);
    const auto mix = [](float a, float b) { return a * 0.93f + b * 0.07f; };
    draw.AddRectFilled(origin, ImVec2(origin.x + region.x, origin.y + region.y),
                       ImGui::GetColorU32(ImVec4(mix(pane.x, ink.x), mix(pane.y, ink.y), mix(pane.z, ink.z), 1.0f)));
    if (hasImage())
    {
        const float scale = std::min(region.x / float(m_width), region.y / float(m_height));
        const ImVec2 size(float(m_width) * scale, float(m_height) * scale);
        const ImVec2 topLeft(origin.x + (region.x - size.x) * 0.5f, origin.y + (region.y - size.y) * 0.5f);
        const ImU32 tint = dim ? IM_COL32(255, 255, 255, 70) : IM_COL32_WHITE;
        draw.AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(m_texture.id())), topLeft,
                      ImVec2(topLeft.x + size.x, topLeft.y + size.y), ImVec2(0, 0), ImVec2(1, 1), tint);
        m_drawnRect = {topLeft.x, topLeft.y, size.x, size.y};
    }
    if (!overlay.empty())
    {
        const ImVec2 text = ImGui::CalcTextSize(overlay.c_str());
        const ImVec2 at(origin.x + (region.x - text.x) * 0.5f, origin.y + (region.y - text.y) * 0.5f);
        const float pad = ImGui::GetStyle().FramePadding.x * 2.0f;
        draw.AddRectFilled(ImVec2(at.x - pad, at.y - pad), ImVec2(at.x + text.x + pad, at.y + text.y + pad),
                           IM_COL32(0, 0, 0, 170), ImGui::GetStyle().FrameRounding);
        draw.AddText(at, IM_COL32(240, 240, 240, 255), overlay.c_str());
    }
    ImGui::InvisibleButton("image", region); // takes the pane's clicks: a drag turns the camera
    const ImGuiIO& io = ImGui::GetIO();
    ImagePointer pointer;
    pointer.hovered = ImGui::IsItemHovered();
    pointer.dragging = ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f);
    if (pointer.dragging)
    {
        pointer.dragX = io.MouseDelta.x;
        pointer.dragY = io.MouseDelta.y;
    }
    if (pointer.hovered)
        pointer.wheel = io.MouseWheel;
    return pointer;
}
} // namespace rt::gui
