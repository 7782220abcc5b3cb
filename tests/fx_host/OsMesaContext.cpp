// The fx_host's OSMesa context. This file sees GL/osmesa.h (and through it the system GL/gl.h),
// so it must never include glad: GL is called through glad's pointers elsewhere.
#include <GL/osmesa.h>
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "FxTestHost.h"

namespace fxtest {

namespace {

struct OsMesa {
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer;  // OSMesa wants a client colour buffer; we draw into FBOs
};

OsMesa& instance() {
    static OsMesa m;
    return m;
}

// The context lives until the process exits, and llvmpipe's own exit handler then stops its
// rasterizer threads without waiting for work still queued: a thread that had taken a scene waits
// at the scene's barrier for one that took the signal to stop instead, and the handler's join of
// it never returns (seen: 12 of 100 runs of a short test with both cores busy hung after PASSED,
// ctest's 300 s timeout in the full suite). Finishing the work first leaves it nothing to race
// with. Registered after the context was made, so it runs before the handler Mesa registered then.
void finishBeforeMesaExits() { glFinish(); }

}  // namespace

bool osMesaCompatibilityProfile() {
    const char* profile = std::getenv("CUBE_FX_HOST_PROFILE");
    return profile && std::strcmp(profile, "compat") == 0;
}

bool createOsMesaContext(std::string* error) {
    OsMesa& m = instance();
    if (m.context) return true;
    const bool compat = osMesaCompatibilityProfile();
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 24,
                           OSMESA_STENCIL_BITS, 8,
                           OSMESA_PROFILE, compat ? OSMESA_COMPAT_PROFILE : OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3,
                           OSMESA_CONTEXT_MINOR_VERSION, 3,
                           0};
    {
#if defined(__SANITIZE_ADDRESS__)
        // What Mesa's context creation keeps to the end goes unreported under LeakSanitizer
        // (engine_stub/platform/PlatformOSMesa.cpp says why).
        __lsan::ScopedDisabler mesaKeepsThese;
#endif
        m.context = OSMesaCreateContextAttribs(attribs, nullptr);
    }
    if (!m.context) {
        *error = compat ? "OSMesa: cannot create a 3.3 compatibility-profile context"
                        : "OSMesa: cannot create a 3.3 core context";
        return false;
    }
    m.buffer.assign(4 * 4 * 4, 0);
    if (!OSMesaMakeCurrent(m.context, m.buffer.data(), GL_UNSIGNED_BYTE, 4, 4)) {
        *error = "OSMesa: OSMesaMakeCurrent failed";
        OSMesaDestroyContext(m.context);
        m.context = nullptr;
        return false;
    }
    std::atexit(finishBeforeMesaExits);
    return true;
}

bool resizeDefaultFramebuffer(int width, int height) {
    OsMesa& m = instance();
    if (!m.context || width < 1 || height < 1) return false;
    m.buffer.assign(size_t(width) * size_t(height) * 4, 0);
    return OSMesaMakeCurrent(m.context, m.buffer.data(), GL_UNSIGNED_BYTE, width, height) != 0;
}

ProcAddressFn osMesaProcAddress() { return &OSMesaGetProcAddress; }

}  // namespace fxtest
