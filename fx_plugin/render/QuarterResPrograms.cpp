#include "QuarterResPrograms.h"

#include "render/PrivateGl.h"

#include "ShaderLoader.h"
#include "Uniforms.h"

namespace fx {

QuarterResPrograms::~QuarterResPrograms() {
    if (halfZ) glDeleteProgram(halfZ);
    if (downsample) glDeleteProgram(downsample);
    for (const CompositeProgram& c : composite) {
        if (c.program) glDeleteProgram(c.program);
    }
    if (tileVao_) glDeleteVertexArrays(1, &tileVao_);
    if (tileVbo_) glDeleteBuffers(1, &tileVbo_);
}

void QuarterResPrograms::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    hostDepth.create();
    // vs_particles_tiles + `fs` (0 with the failure in *errors), left as it is when built before.
    auto make = [&](uint32_t* program, const char* fs, const char* defines) {
        if (*program) return false;
        std::string error;
        *program = buildProgram(shaderDir, "vs_particles_tiles.glsl", fs, defines, &error);
        if (!*program) errors->push_back(error);
        return *program != 0;
    };
    if (make(&downsample, "fs_particles_depth_downsample.glsl", "")) {
        locateUniforms(downsample, {{&downsampleDepthLoc, "uSceneDepth"}, {&downsampleViewLoc, "uViewSize"},
                                    {&downsampleDecode.coeffs, "uDepthCoeffs"},
                                    {&downsampleDecode.window, "uDepthWindow"},
                                    {&downsampleDecode.drawOrigin, "uDrawOrigin"}});
    }
    if (make(&halfZ, "fs_particles_half_z.glsl", "")) {
        locateUniforms(halfZ, {{&halfZDepthLoc, "uHalfDepth"}, {&halfZFromLinearLoc, "uDepthFromLinear"},
                               {&halfZFarLoc, "uFar"}, {&halfZViewLoc, "uViewSize"}});
    }
    static const char* const kCompositeDefines[CompositeVariantCount] = {
        "", "#define FX_COMPOSITE_BILINEAR 1\n"};
    for (int v = 0; v < CompositeVariantCount; ++v) {
        CompositeProgram& c = composite[v];
        if (!make(&c.program, "fs_particles_composite.glsl", kCompositeDefines[v])) continue;
        locateUniforms(c.program, {{&c.halfColor, "uHalfColor"}, {&c.halfDepth, "uHalfDepth"},
                                   {&c.sceneDepth, "uSceneDepth"}, {&c.threshold, "uDepthThreshold"},
                                   {&c.viewSize, "uViewSize"},
                                   {&c.decode.coeffs, "uDepthCoeffs"},
                                   {&c.decode.window, "uDepthWindow"}, {&c.decode.drawOrigin, "uDrawOrigin"}});
    }
    if (!tileVao_) {
        glGenVertexArrays(1, &tileVao_);
        glGenBuffers(1, &tileVbo_);
        glBindVertexArray(tileVao_);
        glBindBuffer(GL_ARRAY_BUFFER, tileVbo_);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
}

void QuarterResPrograms::drawTiles(int viewSizeLoc, const ScreenTiles& tiles) {
    if (tiles.vertices.empty()) return;
    glUniform2f(viewSizeLoc, float(tiles.viewWidth), float(tiles.viewHeight));
    glBindVertexArray(tileVao_);
    glBindBuffer(GL_ARRAY_BUFFER, tileVbo_);
    // Orphaned every draw: a pass of another view may have drawn its own runs in between.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tiles.vertices.size() * sizeof(float)), tiles.vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(tiles.vertices.size() / 2));
}

}  // namespace fx
