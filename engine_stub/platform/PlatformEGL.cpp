// EGL headless context for machines with a GPU: the Mesa surfaceless platform first, then the
// first EGL device (NVIDIA's driver offers devices, not surfaceless). No surface is made: the
// engine renders into FBOs only.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "platform/Platform.h"

namespace cube {

std::string glRendererString();  // gl/GlLoader.cpp

namespace {

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

class EGLPlatform final : public Platform {
public:
    ~EGLPlatform() override {
        if (display_ != EGL_NO_DISPLAY) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
        }
    }

    bool init(const PlatformDesc& desc, std::string* error) {
        width_ = desc.width;
        height_ = desc.height;
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) {
            *error = "EGL: eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)";
            return false;
        }
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
            display_ = EGL_NO_DISPLAY;
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
                eglGetProcAddress("eglQueryDevicesEXT"));
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (queryDevices && queryDevices(8, devices, &count) && count > 0) {
                for (EGLint i = 0; i < count && display_ == EGL_NO_DISPLAY; ++i) {
                    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) display_ = d;
                }
            }
        }
        if (display_ == EGL_NO_DISPLAY) {
            *error = "EGL: no surfaceless platform and no usable EGL device (no GPU driver?)";
            return false;
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            *error = "EGL: the display does not offer desktop OpenGL";
            return false;
        }
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint numConfigs = 0;
        eglChooseConfig(display_, configAttribs, &config, 1, &numConfigs);
        const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = eglCreateContext(display_, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR,
                                    EGL_NO_CONTEXT, ctxAttribs);
        if (context_ == EGL_NO_CONTEXT) {
            *error = "EGL: could not create a 3.3 core context (error 0x" + hex(eglGetError()) + ")";
            return false;
        }
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            *error = "EGL: surfaceless eglMakeCurrent failed (error 0x" + hex(eglGetError()) + ")";
            return false;
        }
        if (!loadGL(reinterpret_cast<GetProcFn>(&eglGetProcAddress), error)) return false;
        renderer_ = glRendererString();
        return true;
    }

    Backend backend() const override { return Backend::EGL; }
    int width() const override { return width_; }
    int height() const override { return height_; }
    void present() override {}
    bool pollEvents() override { return true; }
    bool keyPressed(Key) override { return false; }
    void resize(int w, int h) override { width_ = w; height_ = h; }
    std::string rendererName() const override { return renderer_; }
    void* getProcAddress(const char* name) const override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

private:
    static std::string hex(EGLint v) {
        static const char* digits = "0123456789ABCDEF";
        std::string s;
        for (int shift = 12; shift >= 0; shift -= 4) s += digits[(v >> shift) & 0xF];
        return s;
    }
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    int width_ = 0, height_ = 0;
    std::string renderer_;
};

}  // namespace

std::unique_ptr<Platform> createEGLPlatform(const PlatformDesc& desc, std::string* error) {
    auto p = std::make_unique<EGLPlatform>();
    if (!p->init(desc, error)) return nullptr;
    return p;
}

}  // namespace cube
