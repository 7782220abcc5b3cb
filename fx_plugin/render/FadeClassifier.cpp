#include "FadeClassifier.h"

#include <algorithm>

#include "render/PrivateGl.h"

#include "DrawList.h"
#include "GlStateGuard.h"
#include "InstanceStream.h"
#include "ShaderLoader.h"
#include "Uniforms.h"

namespace fx {
namespace {

int tilesFor(int pixels, int tileSize) { return std::max(1, (pixels + tileSize - 1) / tileSize); }

}  // namespace

FadeClassifier::~FadeClassifier() {
    if (tileProgram_) glDeleteProgram(tileProgram_);
    if (coarseProgram_) glDeleteProgram(coarseProgram_);
    if (countProgram_) glDeleteProgram(countProgram_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (counterFbo_) glDeleteFramebuffers(1, &counterFbo_);
    if (counter_) glDeleteTextures(1, &counter_);
}

void FadeClassifier::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    build(snapshotShaderReader(shaderReader(shaderDir)), errors);
}

void FadeClassifier::readSources(const ShaderReader& read) {
    for (const char* file : {"vs_particles_fullscreen.glsl", "fs_particles_tile_depth.glsl", "vs_particles_count.glsl",
                             "fs_particles_count.glsl"}) {
        ShaderSource ignored;
        std::string error;  // a file that cannot be read is reported by the build that needs it
        (void)expandShaderSource(read, file, "", &ignored, &error);
    }
}

void FadeClassifier::build(const ShaderReader& shaderDir, std::vector<std::string>* errors) {
    hostDepth_.create();
    std::string error;
    // The fine tiles from the scene depth, the coarse ones from the fine tiles: one shader.
    struct TileBuild {
        uint32_t* program;
        int* source;
        const char* defines;
    };
    for (const TileBuild& t : {TileBuild{&tileProgram_, &tileSourceLoc_, ""},
                               TileBuild{&coarseProgram_, &coarseSourceLoc_, "#define FX_TILE_COARSE 1\n"}}) {
        if (*t.program) continue;
        *t.program = buildProgram(shaderDir, "vs_particles_fullscreen.glsl", "fs_particles_tile_depth.glsl",
                                  t.defines, &error);
        if (*t.program) {
            *t.source = glGetUniformLocation(*t.program, "uSource");
            if (t.program == &tileProgram_) {
                tileDecodeLoc_.locate(tileProgram_);
            }
        } else {
            errors->push_back(error);
        }
    }
    if (!countProgram_) {
        countProgram_ = buildProgram(shaderDir, "vs_particles_count.glsl", "fs_particles_count.glsl", "", &error);
        if (countProgram_) {
            locateUniforms(countProgram_, {{&countView_, "uView"}, {&countProj_, "uProj"}, {&countNear_, "uNear"},
                                           {&countSoftScale_, "uSoftScale"}, {&countSphere_, "uSphere"},
                                           {&countTiles_, "uTiles"}, {&countCoarse_, "uTilesCoarse"},
                                           {&countViewSize_, "uViewSize"}});
        } else {
            errors->push_back(error);
        }
    }
    if (!vao_) glGenVertexArrays(1, &vao_);
    if (!counter_) {
        glActiveTexture(GL_TEXTURE0);  // the caller's guard restores unit 0
        glGenTextures(1, &counter_);
        glBindTexture(GL_TEXTURE_2D, counter_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        glGenFramebuffers(1, &counterFbo_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, counterFbo_);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, counter_, 0);
        if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            errors->push_back("fade classification: the RGBA32F counter target is not renderable");
            glDeleteFramebuffers(1, &counterFbo_);
            counterFbo_ = 0;
        }
    }
}

bool FadeClassifier::ok() const {
    return tileProgram_ && coarseProgram_ && countProgram_ && counterFbo_;
}

TargetDesc FadeClassifier::tileTargetDesc(int width, int height, bool coarse) {
    TargetDesc d;
    const int tile = coarse ? kCoarseTileSize : kTileSize;
    d.width = tilesFor(width, tile);
    d.height = tilesFor(height, tile);
    d.format = TargetFormat::RG32F;
    d.linearFilter = false;
    return d;
}

void FadeClassifier::buildTiles(PassContext& ctx, Target sceneDepth, const SceneDepthDecode& decode, Target tiles,
                                Target coarse) {
    plainDrawState();
    glBindVertexArray(vao_);

    ctx.bindForDraw(tiles);
    glUseProgram(tileProgram_);
    hostDepth_.bindTexture(0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(tileSourceLoc_, 0);
    setSceneDepthDecode(tileDecodeLoc_, decode);
    sceneDepthBarrier(decode);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    ctx.bindForDraw(coarse);
    glUseProgram(coarseProgram_);
    bindTextureUnit(0, ctx.texture(tiles, 0).name);
    glUniform1i(coarseSourceLoc_, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

FadeClassCounts FadeClassifier::count(const std::vector<DrawBatch>& batches, InstanceStream& stream,
                                      const ViewInfo& view, uint32_t tiles, uint32_t coarse) {
    FadeClassCounts counts;
    if (!countProgram_ || !counterFbo_) return counts;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, counterFbo_);
    glViewport(0, 0, 1, 1);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(countProgram_);
    glUniformMatrix4fv(countView_, 1, GL_FALSE, &view.view[0][0]);
    glUniformMatrix4fv(countProj_, 1, GL_FALSE, &view.proj[0][0]);
    glUniform1f(countNear_, view.nearPlane);
    glUniform2f(countViewSize_, float(view.width), float(view.height));
    bindTextureUnit(kTileUnit, tiles);
    bindTextureUnit(kCoarseUnit, coarse);
    glUniform1i(countTiles_, kTileUnit);
    glUniform1i(countCoarse_, kCoarseUnit);
    for (const DrawBatch& batch : batches) {
        if (batch.technique != Technique::Soft && batch.technique != Technique::Spherical) continue;
        glUniform1f(countSoftScale_, batch.softScale);
        glUniform1i(countSphere_, batch.technique == Technique::Spherical ? 1 : 0);
        stream.bindRange(batch.first);
        glDrawArraysInstanced(GL_POINTS, 0, 1, batch.count);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, counterFbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    float sums[4] = {};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, sums);
    counts.fadeNeeded = int(sums[0] + 0.5f);
    counts.inFront = int(sums[1] + 0.5f);
    counts.hidden = int(sums[2] + 0.5f);
    counts.counted = true;
    return counts;
}

}  // namespace fx
