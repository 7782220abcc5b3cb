#include "platform/Platform.h"

#include <algorithm>
#include <cctype>

namespace cube {

const char* backendName(Backend backend) {
    switch (backend) {
        case Backend::OSMesa: return "osmesa";
        case Backend::EGL: return "egl";
        case Backend::GLFW: return "glfw";
    }
    return "?";
}

bool parseBackend(const std::string& text, Backend* out) {
    if (text == "osmesa") { *out = Backend::OSMesa; return true; }
    if (text == "egl") { *out = Backend::EGL; return true; }
    if (text == "glfw") { *out = Backend::GLFW; return true; }
    return false;
}

std::unique_ptr<Platform> Platform::create(const PlatformDesc& desc, std::string* error) {
    if (desc.width < 0 || desc.height < 0 || desc.width > 16384 || desc.height > 16384) {
        *error = "window size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                 " is outside 0..16384";
        return nullptr;
    }
    switch (desc.backend) {
        case Backend::OSMesa: return createOSMesaPlatform(desc, error);
        case Backend::EGL: return createEGLPlatform(desc, error);
        case Backend::GLFW: return createGLFWPlatform(desc, error);
    }
    *error = "unknown backend";
    return nullptr;
}

bool Platform::softwareRenderer() const {
    std::string r = rendererName();
    std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return std::tolower(c); });
    return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos ||
           r.find("swrast") != std::string::npos || r.find("software") != std::string::npos;
}

}  // namespace cube
