// OSMesa headless context. This file sees GL/osmesa.h (and through it the system GL/gl.h), so
// it must never include glad; GL calls go through loadGL's function pointers elsewhere.
// libOSMesa is opened at run time (platform/SystemLibrary.h): the header gives types and
// constants only, every OSMesa call goes through api_.
#include <GL/osmesa.h>
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include <vector>

#include "platform/Platform.h"
#include "platform/SystemLibrary.h"

namespace cube {

std::string glRendererString();  // gl/GlLoader.cpp

namespace {

// The entry points this back end uses, each resolved by its own name from libOSMesa.
#define CUBE_OSMESA_FUNCTIONS(X) \
    X(OSMesaCreateContextAttribs) X(OSMesaMakeCurrent) X(OSMesaDestroyContext) X(OSMesaGetProcAddress)

struct OSMesaApi {
    CUBE_SYSTEM_LIBRARY_TABLE(CUBE_OSMESA_FUNCTIONS)
};

bool loadOSMesa(OSMesaApi* api, std::string* error) {
    return loadSystemLibrary({"osmesa", "libOSMesa.so.8", "CUBE_OSMESA_LIBRARY", "Debian's libosmesa6"}, api, error);
}

class OSMesaPlatform final : public HeadlessPlatform {
public:
    ~OSMesaPlatform() override {
        if (ctx_) {
            api_.OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
            api_.OSMesaDestroyContext(ctx_);
        }
    }

    bool init(const PlatformDesc& desc, std::string* error) {
        if (!loadOSMesa(&api_, error)) return false;
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                               OSMESA_DEPTH_BITS, 24,
                               OSMESA_STENCIL_BITS, 8,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 3,
                               OSMESA_CONTEXT_MINOR_VERSION, 3,
                               0};
        {
#if defined(__SANITIZE_ADDRESS__)
            // Mesa keeps a few allocations of its context creation to the end (three, 320 bytes).
            // Reported, each would be matched against scripts/lsan.supp, which symbolizes its
            // stack: 0.2 s at every exit of a sanitized process. Nothing of ours is allocated here.
            __lsan::ScopedDisabler mesaKeepsThese;
#endif
            ctx_ = api_.OSMesaCreateContextAttribs(attribs, nullptr);
        }
        if (!ctx_) {
            *error = "OSMesa: could not create a 3.3 core context (is libosmesa6 installed?)";
            return false;
        }
        if (!makeCurrent(desc.width, desc.height)) {
            *error = "OSMesa: OSMesaMakeCurrent failed";
            return false;
        }
        if (!loadGL(reinterpret_cast<GetProcFn>(api_.OSMesaGetProcAddress), error)) return false;
        renderer_ = glRendererString();
        return true;
    }

    Backend backend() const override { return Backend::OSMesa; }
    void resize(int w, int h) override { makeCurrent(w, h); }
    void* getProcAddress(const char* name) const override {
        return reinterpret_cast<void*>(api_.OSMesaGetProcAddress(name));
    }

private:
    // OSMesa needs a client colour buffer even though the engine renders into FBOs; a 0x0
    // request (a "minimised" headless view) keeps a 1x1 buffer and reports 0x0.
    bool makeCurrent(int w, int h) {
        width_ = w;
        height_ = h;
        const int bw = w > 0 ? w : 1, bh = h > 0 ? h : 1;
        buffer_.assign(size_t(bw) * size_t(bh) * 4u, 0);
        return api_.OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, bw, bh) == GL_TRUE;
    }

    OSMesaApi api_;
    OSMesaContext ctx_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Platform> createOSMesaPlatform(const PlatformDesc& desc, std::string* error) {
    return initialisedPlatform<OSMesaPlatform>(desc, error);
}

}  // namespace cube
