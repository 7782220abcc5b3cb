// EGL headless context for machines with a GPU: the Mesa surfaceless platform first, then the
// first EGL device (NVIDIA's driver offers devices, not surfaceless). No surface is made: the
// engine renders into FBOs only. libEGL (glvnd's dispatcher) is opened at run time
// (platform/SystemLibrary.h): the headers give types and constants only, every EGL call goes
// through api_. The vendor driver behind it (libEGL_mesa, NVIDIA's) is glvnd's to find.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "platform/Platform.h"
#include "platform/SystemLibrary.h"

namespace cube {

std::string glRendererString();  // gl/GlLoader.cpp

namespace {

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

// The EGL 1.4 core entry points this back end uses, each resolved by its own name from libEGL;
// extensions (eglGetPlatformDisplayEXT, eglQueryDevicesEXT) come from eglGetProcAddress as before.
#define CUBE_EGL_FUNCTIONS(X)                                                                      \
    X(eglGetProcAddress) X(eglGetError) X(eglInitialize) X(eglTerminate) X(eglBindAPI)             \
    X(eglChooseConfig) X(eglCreateContext) X(eglDestroyContext) X(eglMakeCurrent)

struct EGLApi {
    CUBE_SYSTEM_LIBRARY_TABLE(CUBE_EGL_FUNCTIONS)
};

bool loadEGL(EGLApi* api, std::string* error) {
    return loadSystemLibrary({"egl", "libEGL.so.1", "CUBE_EGL_LIBRARY",
                              "Debian's libegl1 and a vendor driver (libegl-mesa0, or the GPU vendor's)"},
                             api, error);
}

class EGLPlatform final : public HeadlessPlatform {
public:
    ~EGLPlatform() override {
        if (display_ != EGL_NO_DISPLAY) {
            api_.eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) api_.eglDestroyContext(display_, context_);
            api_.eglTerminate(display_);
        }
    }

    bool init(const PlatformDesc& desc, std::string* error) {
        if (!loadEGL(&api_, error)) return false;
        width_ = desc.width;
        height_ = desc.height;
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            api_.eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) {
            *error = "EGL: eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)";
            return false;
        }
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY || !api_.eglInitialize(display_, nullptr, nullptr)) {
            display_ = EGL_NO_DISPLAY;
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
                api_.eglGetProcAddress("eglQueryDevicesEXT"));
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (queryDevices && queryDevices(8, devices, &count) && count > 0) {
                for (EGLint i = 0; i < count && display_ == EGL_NO_DISPLAY; ++i) {
                    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY && api_.eglInitialize(d, nullptr, nullptr)) display_ = d;
                }
            }
        }
        if (display_ == EGL_NO_DISPLAY) {
            *error = "EGL: no surfaceless platform and no usable EGL device (no vendor driver? "
                     "install Debian's libegl-mesa0, or the GPU vendor's EGL driver)";
            return false;
        }
        if (!api_.eglBindAPI(EGL_OPENGL_API)) {
            *error = "EGL: the display does not offer desktop OpenGL";
            return false;
        }
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint numConfigs = 0;
        api_.eglChooseConfig(display_, configAttribs, &config, 1, &numConfigs);
        const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = api_.eglCreateContext(display_, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR,
                                         EGL_NO_CONTEXT, ctxAttribs);
        if (context_ == EGL_NO_CONTEXT) {
            *error = "EGL: could not create a 3.3 core context (error 0x" + hex(api_.eglGetError()) + ")";
            return false;
        }
        if (!api_.eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            *error = "EGL: surfaceless eglMakeCurrent failed (error 0x" + hex(api_.eglGetError()) + ")";
            return false;
        }
        if (!loadGL(reinterpret_cast<GetProcFn>(api_.eglGetProcAddress), error)) return false;
        renderer_ = glRendererString();
        return true;
    }

    Backend backend() const override { return Backend::EGL; }
    void resize(int w, int h) override { width_ = w; height_ = h; }
    void* getProcAddress(const char* name) const override {
        return reinterpret_cast<void*>(api_.eglGetProcAddress(name));
    }

private:
    static std::string hex(EGLint v) {
        static const char* digits = "0123456789ABCDEF";
        std::string s;
        for (int shift = 12; shift >= 0; shift -= 4) s += digits[(v >> shift) & 0xF];
        return s;
    }
    EGLApi api_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Platform> createEGLPlatform(const PlatformDesc& desc, std::string* error) {
    return initialisedPlatform<EGLPlatform>(desc, error);
}

}  // namespace cube
