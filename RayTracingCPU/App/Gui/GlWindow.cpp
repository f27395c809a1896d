#include "App/Gui/GlWindow.h"

#include <algorithm>
#include <atomic>
#include <string>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "Error.h"

namespace rt::gui
{
namespace
{
std::string g_lastGlfwError = "unknown GLFW error";
std::uint64_t g_inputEvents = 0; // GLFW calls the callbacks on the UI thread, inside waitEvents
std::atomic<bool> g_woken{false}; // set by wake(), from any thread

void onGlfwError(int code, const char* description)
{
    g_lastGlfwError = std::string(description ? description : "?") + " (GLFW error " + std::to_string(code) + ")";
}

/// Counts a person's input. Installed before ImGui's backend, which calls them before its own (it chains
/// the callbacks it finds), and on the cursor's moves, which ImGui 1.86 polls rather than hears. A move
/// counts only with a button held (a slider dragged): the pointer crossing the window, or the window opening
/// under it (GLFW reports a move on entering), asks for nothing.
void countInput(GLFWwindow* window)
{
    glfwSetKeyCallback(window, [](GLFWwindow*, int, int, int, int) { ++g_inputEvents; });
    glfwSetCharCallback(window, [](GLFWwindow*, unsigned int) { ++g_inputEvents; });
    glfwSetMouseButtonCallback(window, [](GLFWwindow*, int, int, int) { ++g_inputEvents; });
    glfwSetScrollCallback(window, [](GLFWwindow*, double, double) { ++g_inputEvents; });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) {
        for (int button = GLFW_MOUSE_BUTTON_1; button <= GLFW_MOUSE_BUTTON_LAST; ++button)
            if (glfwGetMouseButton(w, button) == GLFW_PRESS)
            {
                ++g_inputEvents;
                return;
            }
    });
}
} // namespace

GlWindow::Glfw::Glfw()
{
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw Error("cannot open a window: " + g_lastGlfwError +
                    "; run with --headless, or under a display (xvfb-run -a ray-tracing-cpu ...)");
}

GlWindow::Glfw::~Glfw() { glfwTerminate(); }

void GlWindow::WindowDeleter::operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }

GlWindow::ImGuiBackends::ImGuiBackends(GLFWwindow* window)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // the layout is fixed: nothing to remember, no imgui.ini left behind
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330");
}

GlWindow::ImGuiBackends::~ImGuiBackends()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

GlWindow::GlWindow(WindowSize size, bool fitToMonitor, const std::string& title)
{
    if (fitToMonitor)
        if (GLFWmonitor* monitor = glfwGetPrimaryMonitor())
        {
            WindowSize workArea;
            glfwGetMonitorWorkarea(monitor, nullptr, nullptr, &workArea.width, &workArea.height);
            size = fitWindowSize(size, workArea);
        }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    m_window.reset(glfwCreateWindow(size.width, size.height, title.c_str(), nullptr, nullptr));
    if (!m_window)
        throw Error("cannot open a window: " + g_lastGlfwError);
    glfwMakeContextCurrent(m_window.get());
    glfwSwapInterval(1);
    countInput(m_window.get());
    m_imgui = std::make_unique<ImGuiBackends>(m_window.get());
}

// Members go in reverse order: the ImGui backends (their GL objects while the context exists), the window,
// then GLFW.
GlWindow::~GlWindow() = default;

bool GlWindow::closeRequested() const { return glfwWindowShouldClose(m_window.get()); }

void GlWindow::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }

FramebufferSize GlWindow::framebufferSize() const
{
    FramebufferSize size;
    glfwGetFramebufferSize(m_window.get(), &size.width, &size.height);
    return size;
}

void GlWindow::resize(int width, int height)
{
    // X11 ends the process on a 0-pixel window (BadValue from ConfigureWindow): 1 is its smallest size. A
    // true 0x0 framebuffer (minimised on Windows) is what framebufferSize().empty() guards against.
    glfwSetWindowSize(m_window.get(), std::max(width, 1), std::max(height, 1));
}

std::uint64_t GlWindow::inputEvents() const { return g_inputEvents; }

bool GlWindow::cameraKeyHeld() const
{
    for (const int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
        if (glfwGetKey(m_window.get(), key) == GLFW_PRESS)
            return true;
    return false;
}

void GlWindow::wake()
{
    g_woken = true;
    glfwPostEmptyEvent();
}

bool GlWindow::takeWake() { return g_woken.exchange(false); }

void GlWindow::beginFrame()
{
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void GlWindow::endFrame(float clearGrey)
{
    ImGui::Render();
    const FramebufferSize size = framebufferSize();
    glViewport(0, 0, size.width, size.height);
    glClearColor(clearGrey, clearGrey, clearGrey, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void GlWindow::present() { glfwSwapBuffers(m_window.get()); }
} // namespace rt::gui
