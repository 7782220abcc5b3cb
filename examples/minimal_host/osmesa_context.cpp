// The example's GL context: OSMesa, headless. GL/osmesa.h brings the system GL/gl.h, which must
// never meet glad's header, so this is its own translation unit.
#include <GL/osmesa.h>

#include <vector>

#include "host.h"

namespace {
OSMesaContext g_context = nullptr;
std::vector<unsigned char> g_buffer(16 * 16 * 4);  // OSMesa needs a client buffer; we draw into FBOs
}  // namespace

bool createContext() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    g_context = OSMesaCreateContextAttribs(attribs, nullptr);
    return g_context && OSMesaMakeCurrent(g_context, g_buffer.data(), GL_UNSIGNED_BYTE, 16, 16);
}

void destroyContext() {
    if (g_context) OSMesaDestroyContext(g_context);
    g_context = nullptr;
}

void* procAddress(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
