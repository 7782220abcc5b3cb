// A real window through GLFW (needs a display; `xvfb-run -a` on a headless machine). libglfw is
// opened at run time (platform/SystemLibrary.h): the header gives types and constants only,
// every GLFW call goes through the table g_glfw.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>

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
    X(glfwWindowShouldClose) X(glfwIconifyWindow) X(glfwRestoreWindow) X(glfwSetWindowSize)

struct GLFWApi {
#define CUBE_DECLARE(name) decltype(&::name) name = nullptr;
    CUBE_GLFW_FUNCTIONS(CUBE_DECLARE)
#undef CUBE_DECLARE
};

// One table per process, like GLFW's own state: the key callback (a plain function) needs it
// too. Filled by loadGLFW before any window exists; a failed load leaves it as it was.
GLFWApi g_glfw;

bool loadGLFW(std::string* error) {
    SystemLibraryDesc desc;
    desc.backend = "glfw";
    desc.soname = "libglfw.so.3";
    desc.overrideEnv = "CUBE_GLFW_LIBRARY";
    desc.install = "Debian's libglfw3";
    SystemLibrary lib;
    if (!lib.open(desc, error)) return false;
    GLFWApi api;
#define CUBE_RESOLVE(name) if (!lib.resolve(#name, &api.name, error)) return false;
    CUBE_GLFW_FUNCTIONS(CUBE_RESOLVE)
#undef CUBE_RESOLVE
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
            if (action != GLFW_PRESS) return;
            auto* self = static_cast<GLFWPlatform*>(g_glfw.glfwGetWindowUserPointer(w));
            switch (key) {
                case GLFW_KEY_P: self->pressed_[size_t(Key::P)] = true; break;
                case GLFW_KEY_Q: self->pressed_[size_t(Key::Q)] = true; break;
                case GLFW_KEY_M: self->pressed_[size_t(Key::M)] = true; break;
                case GLFW_KEY_H: self->pressed_[size_t(Key::H)] = true; break;
                case GLFW_KEY_S: self->pressed_[size_t(Key::S)] = true; break;
                case GLFW_KEY_B: self->pressed_[size_t(Key::B)] = true; break;
                case GLFW_KEY_ESCAPE: self->pressed_[size_t(Key::Escape)] = true; break;
                default: break;
            }
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
    void* getProcAddress(const char* name) const override {
        return reinterpret_cast<void*>(g_glfw.glfwGetProcAddress(name));
    }

private:
    GLFWwindow* window_ = nullptr;
    bool initialised_ = false;
    std::array<bool, size_t(Key::Count)> pressed_{};
    std::string renderer_;
};

}  // namespace

std::unique_ptr<Platform> createGLFWPlatform(const PlatformDesc& desc, std::string* error) {
    auto p = std::make_unique<GLFWPlatform>();
    if (!p->init(desc, error)) return nullptr;
    return p;
}

}  // namespace cube
