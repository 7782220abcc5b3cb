// A real window through GLFW (needs a display; `xvfb-run -a` on a headless machine).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>

#include "platform/Platform.h"

namespace cube {

std::string glRendererString();  // gl/GlLoader.cpp

namespace {

std::string g_glfwError;
void onGlfwError(int code, const char* text) {
    g_glfwError = "GLFW error " + std::to_string(code) + ": " + (text ? text : "");
}

class GLFWPlatform final : public Platform {
public:
    ~GLFWPlatform() override {
        if (window_) glfwDestroyWindow(window_);
        if (initialised_) glfwTerminate();
    }

    bool init(const PlatformDesc& desc, std::string* error) {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit()) {
            *error = "GLFW: cannot initialise (no display? run under xvfb-run -a). " + g_glfwError;
            return false;
        }
        initialised_ = true;
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.debugContext ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(desc.width > 0 ? desc.width : 1, desc.height > 0 ? desc.height : 1,
                                   desc.title.c_str(), nullptr, nullptr);
        if (!window_) {
            *error = "GLFW: cannot open a 3.3 core window. " + g_glfwError;
            return false;
        }
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(0);
        glfwSetWindowUserPointer(window_, this);
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
            if (action != GLFW_PRESS) return;
            auto* self = static_cast<GLFWPlatform*>(glfwGetWindowUserPointer(w));
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
        if (!loadGL(reinterpret_cast<GetProcFn>(&glfwGetProcAddress), error)) return false;
        renderer_ = glRendererString();
        return true;
    }

    Backend backend() const override { return Backend::GLFW; }
    int width() const override { int w, h; glfwGetFramebufferSize(window_, &w, &h); return w; }
    int height() const override { int w, h; glfwGetFramebufferSize(window_, &w, &h); return h; }
    void present() override { glfwSwapBuffers(window_); }
    bool pollEvents() override {
        glfwPollEvents();
        if (pressed_[size_t(Key::Escape)]) glfwSetWindowShouldClose(window_, GLFW_TRUE);
        return !glfwWindowShouldClose(window_);
    }
    bool keyPressed(Key key) override {
        bool was = pressed_[size_t(key)];
        pressed_[size_t(key)] = false;
        return was;
    }
    void resize(int w, int h) override {
        if (w <= 0 || h <= 0) glfwIconifyWindow(window_);
        else { glfwRestoreWindow(window_); glfwSetWindowSize(window_, w, h); }
    }
    std::string rendererName() const override { return renderer_; }
    void* getProcAddress(const char* name) const override { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

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
