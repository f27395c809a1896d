#include "App/Gui/Screenshot.h"

#include <algorithm>
#include <vector>

#include <GL/gl.h>

#include "Image/ImageIO.h"

namespace rt::gui
{
void saveScreenshot(const std::filesystem::path& path, FramebufferSize size)
{
    const std::size_t row = std::size_t(size.width) * 4;
    std::vector<unsigned char> pixels(row * std::size_t(size.height));
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // GL's row 0 is the bottom one; and what is on screen is opaque whatever alpha the blending left.
    std::vector<unsigned char> topDown(pixels.size());
    for (int y = 0; y < size.height; ++y)
        std::copy_n(pixels.data() + std::size_t(size.height - 1 - y) * row, row, topDown.data() + std::size_t(y) * row);
    for (std::size_t i = 3; i < topDown.size(); i += 4)
        topDown[i] = 255;
    writePng8(path, size.width, size.height, topDown);
}
} // namespace rt::gui
