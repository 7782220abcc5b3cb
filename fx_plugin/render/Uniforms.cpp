#include "Uniforms.h"

#include "render/PrivateGl.h"

namespace fx {

void locateUniforms(uint32_t program, std::initializer_list<UniformSlot> slots) {
    if (!program) return;
    for (const UniformSlot& s : slots) *s.location = glGetUniformLocation(GLuint(program), s.name);
}

}  // namespace fx
