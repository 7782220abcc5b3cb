#include "gl/Paths.h"

#include <cstdlib>

namespace cube::paths {

std::string root() {
    if (const char* env = std::getenv("CUBE_ROOT"); env && *env) return env;
    return CUBE_SOURCE_DIR;
}
std::string shaders() {
    if (const char* env = std::getenv("CUBE_SHADER_DIR"); env && *env) return env;
    return root() + "/shaders";
}
std::string shaderOverride() {
    const char* env = std::getenv("CUBE_SHADER_DIR");
    return env && *env ? env : std::string();
}
std::string data() { return root() + "/data"; }
std::string reactions() { return root() + "/reactions"; }

}  // namespace cube::paths
