// The desktop window: GLFW, an OpenGL 3.3 context and Dear ImGui's GLFW and OpenGL3 backends, created in
// that order and torn down in reverse by the members' destructors. OpenGL, not Vulkan: the process's one
// Vulkan device belongs to the GPU engine (GpuStartup.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "Cli/WindowSize.h"

struct GLFWwindow;

namespace rt::gui
{
struct FramebufferSize
{
    int width = 0;
    int height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

class GlWindow
{
public:
    /// Opens a window of `size` (--window-size), or, with `fitToMonitor`, of `size` cut to the primary
    /// monitor's work area (the default size is made to fit the panes, not the screen). Throws rt::Error when
    /// no window can be opened (no display), naming GLFW's reason.
    GlWindow(WindowSize size, bool fitToMonitor, const std::string& title);
    ~GlWindow();
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;

    bool closeRequested() const;
    /// Processes input, sleeping up to `timeoutSeconds` when there is none: the window redraws only as
    /// often as it needs to and leaves the cores to the renderer.
    void waitEvents(double timeoutSeconds);
    /// In pixels; empty while minimised or sized 0x0, when nothing may be drawn.
    FramebufferSize framebufferSize() const;
    /// Sizes the window's content area in screen pixels; 0 becomes 1 where the platform has no empty windows.
    void resize(int width, int height);
    /// Input a person gave so far (keys, characters, mouse buttons, moves and wheel):
    /// the frame loop tells a redraw it had to make for a person from one it chose to make.
    std::uint64_t inputEvents() const;
    /// A camera key (W, A, S, D, Q, E: Scene/CameraMoves.h) is down now.
    bool cameraKeyHeld() const;
    /// Wakes waitEvents from another thread (the render thread, when a render ends). Not counted as input.
    static void wake();
    /// Whether wake() was called since the last call.
    static bool takeWake();

    /// Between beginFrame and endFrame, ImGui calls build the frame; endFrame draws it into the back buffer
    /// (where a screenshot reads it) and present shows it.
    void beginFrame();
    void endFrame(float clearGrey);
    void present();

private:
    struct Glfw
    {
        Glfw();
        ~Glfw();
    };
    struct WindowDeleter
    {
        void operator()(GLFWwindow* window) const;
    };
    struct ImGuiBackends
    {
        explicit ImGuiBackends(GLFWwindow* window);
        ~ImGuiBackends();
    };

    Glfw m_glfw;
    std::unique_ptr<GLFWwindow, WindowDeleter> m_window;
    std::unique_ptr<ImGuiBackends> m_imgui;
};
} // namespace rt::gui
