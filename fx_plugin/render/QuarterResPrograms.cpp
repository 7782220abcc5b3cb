#include "QuarterResPrograms.h"

#include "render/PrivateGl.h"

#include "Uniforms.h"

namespace fx {

QuarterResPrograms::~QuarterResPrograms() {
    if (tileVao_) glDeleteVertexArrays(1, &tileVao_);
    if (tileVbo_) glDeleteBuffers(1, &tileVbo_);
}

void QuarterResPrograms::bind(const ProgramCache& programs) {
    hostDepth.create();
    halfColorSampler.create();
    downsample = programs.passProgram(ProgramCache::DepthDownsample);
    locateUniforms(downsample, {{&downsampleDepthLoc, "uSceneDepth"}, {&downsampleViewLoc, "uViewSize"},
                                {&downsampleCornerLoc, "uCornerUv"},
                                {&downsampleDecode.coeffs, "uDepthCoeffs"},
                                {&downsampleDecode.window, "uDepthWindow"},
                                {&downsampleDecode.drawOrigin, "uDrawOrigin"}});
    halfZ = programs.passProgram(ProgramCache::HalfZ);
    locateUniforms(halfZ, {{&halfZDepthLoc, "uHalfDepth"}, {&halfZFromLinearLoc, "uDepthFromLinear"},
                           {&halfZFarLoc, "uFar"}, {&halfZViewLoc, "uViewSize"}});
    static const ProgramCache::Program kComposite[CompositeVariantCount] = {ProgramCache::Composite,
                                                                            ProgramCache::CompositeBilinear};
    for (int v = 0; v < CompositeVariantCount; ++v) {
        CompositeProgram& c = composite[v];
        c.program = programs.passProgram(kComposite[v]);
        locateUniforms(c.program, {{&c.halfColor, "uHalfColor"}, {&c.halfDepth, "uHalfDepth"},
                                   {&c.sceneDepth, "uSceneDepth"}, {&c.threshold, "uDepthThreshold"},
                                   {&c.viewSize, "uViewSize"},
                                   {&c.decode.coeffs, "uDepthCoeffs"},
                                   {&c.decode.window, "uDepthWindow"}, {&c.decode.drawOrigin, "uDrawOrigin"},
                                   {&c.decode.uv, "uDepthUv"}, {&c.lowMap, "uLowMap"}, {&c.invLow, "uInvLow"}});
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
