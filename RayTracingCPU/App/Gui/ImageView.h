// The rendered image in the window: the newest preview uploaded as an OpenGL texture, drawn as large as the
// pane allows at its own aspect ratio, centred. An image rendered with other settings than the panel shows
// is drawn dimmed under a line that says so, so the picture never passes for the settings beside it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "App/Gui/RenderJob.h"

namespace rt::gui
{
/// One GL texture name, deleted with the object (the GL context must outlive it).
class GlTexture
{
public:
    GlTexture();
    ~GlTexture();
    GlTexture(const GlTexture&) = delete;
    GlTexture& operator=(const GlTexture&) = delete;

    /// RGBA8, row 0 at the top (drawn with v from 0 at the top).
    void upload(int width, int height, const unsigned char* rgba);
    unsigned id() const { return m_id; }

private:
    unsigned m_id = 0;
    int m_width = 0;
    int m_height = 0;
};

/// What the pointer did over the image pane in the last draw(): the camera's input (CameraInput.h).
struct ImagePointer
{
    bool hovered = false;
    bool dragging = false; // the left button went down on the pane and is still down
    float dragX = 0.0f; // this frame's movement while dragging, in screen pixels
    float dragY = 0.0f;
    float wheel = 0.0f; // steps while hovered
};

class ImageView
{
public:
    /// Uploads `preview` when it is newer than the image shown, or `heatmap` changed: with it, the preview's
    /// painted cost map where it has one (Preview::costRgba), else its image.
    void update(const std::shared_ptr<const Preview>& preview, bool heatmap = false);
    /// Whether the texture holds a cost map rather than an image.
    bool showsHeatmap() const { return m_showsHeatmap; }
    /// Draws into the current ImGui window's remaining content region. `overlay`: a line shown over the image
    /// (or the empty pane); `dim`: the image does not belong to the panel's settings.
    ImagePointer draw(bool dim, const std::string& overlay);
    bool hasImage() const { return m_width > 0; }
    /// Where the last draw() put the image, in ImGui's coordinates: x, y, width, height (zeros before).
    const std::array<float, 4>& drawnRect() const { return m_drawnRect; }

private:
    GlTexture m_texture;
    std::uint64_t m_generation = 0;
    bool m_showsHeatmap = false;
    int m_width = 0;
    int m_height = 0;
    std::array<float, 4> m_drawnRect{};
};
} // namespace rt::gui
