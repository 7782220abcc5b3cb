#pragma once
// A program's uniform locations, looked up from one table: the programs of the render paths
// (quarter res, mega, the opacity map, the depth lineariser) each name their uniforms once,
// beside the member that keeps the location.
#include <cstdint>
#include <initializer_list>

namespace fx {

struct UniformSlot {
    int* location;     ///< where the location goes (-1 when the program does not use it)
    const char* name;  ///< the uniform's name in the GLSL source
};

/// Looks every slot's uniform up in `program` (in use or not; changes no GL state). Nothing for
/// program 0 (a build that failed): the slots keep what they held.
void locateUniforms(uint32_t program, std::initializer_list<UniformSlot> slots);

}  // namespace fx
