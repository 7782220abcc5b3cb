// A real window through GLFW (needs a display; `xvfb-run -a` on a headless machine). libglfw is
// opened at run time (platform/SystemLibrary.h): the header gives types and constants only,
// every GLFW call goes through the table g_glfw.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>
#include <vector>

#include "platform/Platform.h"
#include "platform/SystemLibrary.h"

namespace cube {

std::string glRendererString();  // gl/GlLoader.cpp

namespace {

// The GLFW 3.3 entry points this back end uses, each resolved by its own name from libglfw.
#define CUBE_GLFW_FUNCTIONS(X)                                                                     \
    X(glfwSetErrorCallback) X(glfwInit) X(glfwTerminate) X(glfwWindowHint) X(glfwCreateWindow)     \
    X(glfwDestroyWindow) X(glfwMakeContextCurrent) X(glfwSwapInterval) X(glfwSetWindowUserPointer) \
    X(glfwGetWindowUserPointer) X(glfwSetKeyCallback) X(glfwGetProcAddress)                        \
    X(glfwGetFramebufferSize) X(glfwSwapBuffers) X(glfwPollEvents) X(glfwSetWindowShouldClose)     \
    X(glfwWindowShouldClose) X(glfwIconifyWindow) X(glfwRestoreWindow) X(glfwSetWindowSize)       \
    X(glfwSetCursorPosCallback) X(glfwSetMouseButtonCallback) X(glfwSetScrollCallback)            \
    X(glfwSetCharCallback) X(glfwGetWindowSize)

struct GLFWApi {
    CUBE_SYSTEM_LIBRARY_TABLE(CUBE_GLFW_FUNCTIONS)
};

// One table per process, like GLFW's own state: the key callback (a plain function) needs it
// too. Filled by loadGLFW before any window exists; a failed load leaves it as it was.
GLFWApi g_glfw;

bool loadGLFW(std::string* error) {
    GLFWApi api;
    if (!loadSystemLibrary({"glfw", "libglfw.so.3", "CUBE_GLFW_LIBRARY", "Debian's libglfw3"}, &api, error))
        return false;
    g_glfw = api;
    return true;
}

std::string g_glfwError;
void onGlfwError(int code, const char* text) {
    g_glfwError = "GLFW error " + std::to_string(code) + ": " + (text ? text : "");
}

class GLFWPlatform final : public Platform {
public:
    ~GLFWPlatform() override {
        if (window_) g_glfw.glfwDestroyWindow(window_);
        if (initialised_) g_glfw.glfwTerminate();
    }

    bool init(const PlatformDesc& desc, std::string* error) {
        if (!loadGLFW(error)) return false;
        g_glfw.glfwSetErrorCallback(onGlfwError);
        if (!g_glfw.glfwInit()) {
            *error = "GLFW: cannot initialise (no display? run under xvfb-run -a). " + g_glfwError;
            return false;
        }
        initialised_ = true;
        g_glfw.glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        g_glfw.glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        g_glfw.glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        g_glfw.glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        g_glfw.glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.debugContext ? GLFW_TRUE : GLFW_FALSE);
        window_ = g_glfw.glfwCreateWindow(desc.width > 0 ? desc.width : 1,
                                          desc.height > 0 ? desc.height : 1, desc.title.c_str(),
                                          nullptr, nullptr);
        if (!window_) {
            *error = "GLFW: cannot open a 3.3 core window. " + g_glfwError;
            return false;
        }
        g_glfw.glfwMakeContextCurrent(window_);
        g_glfw.glfwSwapInterval(0);
        g_glfw.glfwSetWindowUserPointer(window_, this);
        g_glfw.glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            self->queueKey(key, action != GLFW_RELEASE);
            if (action != GLFW_PRESS) return;
            switch (key) {
                case GLFW_KEY_P: self->pressed_[size_t(Key::P)] = true; break;
                case GLFW_KEY_Q: self->pressed_[size_t(Key::Q)] = true; break;
                case GLFW_KEY_M: self->pressed_[size_t(Key::M)] = true; break;
                case GLFW_KEY_H: self->pressed_[size_t(Key::H)] = true; break;
                case GLFW_KEY_B: self->pressed_[size_t(Key::B)] = true; break;
                case GLFW_KEY_E: self->pressed_[size_t(Key::E)] = true; break;
                case GLFW_KEY_ESCAPE: self->pressed_[size_t(Key::Escape)] = true; break;
                default: break;
            }
        });
        g_glfw.glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            InputEvent e;
            e.type = InputEvent::Type::MouseMove;
            // Window coordinates to framebuffer pixels (they differ on high-DPI screens).
            int ww = 1, wh = 1;
            g_glfw.glfwGetWindowSize(w, &ww, &wh);
            e.x = float(x) * float(self->width()) / float(ww > 0 ? ww : 1);
            e.y = float(y) * float(self->height()) / float(wh > 0 ? wh : 1);
            self->queueEvent(e);
        });
        g_glfw.glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            InputEvent e;
            e.type = InputEvent::Type::MouseButton;
            e.button = button;
            e.down = action == GLFW_PRESS;
            self->queueEvent(e);
        });
        g_glfw.glfwSetScrollCallback(window_, [](GLFWwindow* w, double dx, double dy) {
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            InputEvent e;
            e.type = InputEvent::Type::Scroll;
            e.x = float(dx);
            e.y = float(dy);
            self->queueEvent(e);
        });
        g_glfw.glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned codepoint) {
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            InputEvent e;
            e.type = InputEvent::Type::Char;
            e.codepoint = codepoint;
            self->queueEvent(e);
        });
        if (!loadGL(reinterpret_cast<GetProcFn>(g_glfw.glfwGetProcAddress), error)) return false;
        renderer_ = glRendererString();
        return true;
    }

    Backend backend() const override { return Backend::GLFW; }
    int width() const override { int w, h; g_glfw.glfwGetFramebufferSize(window_, &w, &h); return w; }
    int height() const override { int w, h; g_glfw.glfwGetFramebufferSize(window_, &w, &h); return h; }
    void present() override { g_glfw.glfwSwapBuffers(window_); }
    bool pollEvents() override {
        g_glfw.glfwPollEvents();
        if (pressed_[size_t(Key::Escape)]) g_glfw.glfwSetWindowShouldClose(window_, GLFW_TRUE);
        return !g_glfw.glfwWindowShouldClose(window_);
    }
    bool keyPressed(Key key) override {
        bool was = pressed_[size_t(key)];
        pressed_[size_t(key)] = false;
        return was;
    }
    void resize(int w, int h) override {
        if (w <= 0 || h <= 0) g_glfw.glfwIconifyWindow(window_);
        else { g_glfw.glfwRestoreWindow(window_); g_glfw.glfwSetWindowSize(window_, w, h); }
    }
    std::string rendererName() const override { return renderer_; }
    // Bounded: with no UI taking them (no --panel), the oldest events are dropped.
    void queueEvent(const InputEvent& e) {
        if (events_.size() >= kMaxQueuedEvents) events_.erase(events_.begin(), events_.begin() + kMaxQueuedEvents / 2);
        events_.push_back(e);
    }
    static constexpr size_t kMaxQueuedEvents = 4096;
    void takeInputEvents(std::vector<InputEvent>* out) override {
        out->insert(out->end(), events_.begin(), events_.end());
        events_.clear();
    }
    void queueKey(int glfwKey, bool down) {
        static const std::pair<int, UiKey> kKeys[] = {
            {GLFW_KEY_TAB, UiKey::Tab}, {GLFW_KEY_LEFT, UiKey::Left}, {GLFW_KEY_RIGHT, UiKey::Right},
            {GLFW_KEY_UP, UiKey::Up}, {GLFW_KEY_DOWN, UiKey::Down}, {GLFW_KEY_PAGE_UP, UiKey::PageUp},
            {GLFW_KEY_PAGE_DOWN, UiKey::PageDown}, {GLFW_KEY_HOME, UiKey::Home}, {GLFW_KEY_END, UiKey::End},
            {GLFW_KEY_DELETE, UiKey::Delete}, {GLFW_KEY_BACKSPACE, UiKey::Backspace},
            {GLFW_KEY_ENTER, UiKey::Enter}, {GLFW_KEY_KP_ENTER, UiKey::Enter}, {GLFW_KEY_ESCAPE, UiKey::Escape},
            {GLFW_KEY_A, UiKey::A}, {GLFW_KEY_C, UiKey::C}, {GLFW_KEY_V, UiKey::V}, {GLFW_KEY_X, UiKey::X},
            {GLFW_KEY_Y, UiKey::Y}, {GLFW_KEY_Z, UiKey::Z}, {GLFW_KEY_LEFT_CONTROL, UiKey::Ctrl},
            {GLFW_KEY_RIGHT_CONTROL, UiKey::Ctrl}, {GLFW_KEY_LEFT_SHIFT, UiKey::Shift},
            {GLFW_KEY_RIGHT_SHIFT, UiKey::Shift}, {GLFW_KEY_LEFT_ALT, UiKey::Alt}, {GLFW_KEY_RIGHT_ALT, UiKey::Alt}};
        for (const auto& k : kKeys) {
            if (k.first != glfwKey) continue;
            InputEvent e;
            e.type = InputEvent::Type::Key;
            e.key = k.second;
            e.down = down;
            queueEvent(e);
        }
    }
    void* getProcAddress(const char* name) const override {
        return reinterpret_cast<void*>(g_glfw.glfwGetProcAddress(name));
    }

private:
    GLFWwindow* window_ = nullptr;
    bool initialised_ = false;
    std::array<bool, size_t(Key::Count)> pressed_{};
    std::vector<InputEvent> events_;
    std::string renderer_;
};

}  // namespace

std::unique_ptr<Platform> createGLFWPlatform(const PlatformDesc& desc, std::string* error) {
    return initialisedPlatform<GLFWPlatform>(desc, error);
}

}  // namespace cube
