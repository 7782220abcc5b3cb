#pragma once
// The physical limit of a particle pass: one alpha-blended, textured write per pixel the
// particles covered, and nothing else. Particle-pass time / this time says how far a technique
// is from pure fill (overdraw, shader cost, sorting, uploads and extra passes all add to it).
#include <cstdint>
#include <string>
#include <vector>

#include "gl/Gl.h"

#include "gl/Program.h"

namespace cube::rtt {
class RenderTargetPool;
}

namespace cube {

class FillRateProbe : gl::NonCopyable {
public:
    ~FillRateProbe();

    /// Builds the program (shaders/vs_fill_probe.glsl, fs_fill_probe.glsl), a 64x64 RGBA8 texture
    /// and the vertex buffer. Needs the context current.
    bool init(std::string* error);

    /// Builds one quad per horizontal run of covered pixels in `mask` (w x h, rows top-down),
    /// then times drawing them into a w x h RGBA8 target from `pool` with a CPU clock around
    /// glFinish (the upload and one untimed draw come first). Returns the `repeats` draw times in
    /// ms; none for an empty mask. GL state and the pool's free list are left as found (the
    /// target is released).
    std::vector<double> drawTimesMs(rtt::RenderTargetPool& pool, const std::vector<uint8_t>& mask, int w,
                                    int h, int repeats);

private:
    gl::Program program_;
    GLuint texture_ = 0, vao_ = 0, vbo_ = 0;
    std::vector<float> vertices_;
};

}  // namespace cube
