#pragma once
// Files compiled into the library at build time (fx_plugin/cmake/EmbedResources.cmake): the
// particle shaders (shaders/*particles*.glsl) and the smoke atlas (data/smoke_atlas.png), found
// by base name. An installed plugin needs no file beside it.
#include <cstddef>

namespace fx::embedded {

struct Resource {
    const char* name;           ///< base name, e.g. "vs_particles.glsl"
    const unsigned char* data;  ///< `size` bytes followed by a terminating 0 (text is a C string)
    size_t size;
};

/// The resource called `name`, or null.
const Resource* find(const char* name);
int count();
const Resource& at(int index);

}  // namespace fx::embedded
