#include "FogUniforms.h"

#include "render/PrivateGl.h"

namespace fx {

FogUniforms FogUniforms::of(uint32_t program) {
    FogUniforms u;
    if (program == 0) return u;  // a build that failed: nothing to look up (0 is no program)
    u.mode = glGetUniformLocation(program, "uFogMode");
    u.color = glGetUniformLocation(program, "uFogColor");
    u.params = glGetUniformLocation(program, "uFogParams");
    return u;
}

void setFogUniforms(const FogUniforms& at, const Fog& fog) {
    glUniform1i(at.mode, static_cast<int>(fog.mode));
    if (!fog.on()) return;
    glUniform3f(at.color, fog.color.x, fog.color.y, fog.color.z);
    glUniform3f(at.params, fog.start, fog.end, fog.density);
}

}  // namespace fx
