#include "SceneDepthSource.h"

#include "PrivateGl.h"

namespace fx {

SceneDepthDecode SceneDepthDecode::ofZBuffer(const glm::mat4& proj, const DepthMapping& mapping) {
    const LinearizeCoefficients k = linearizeCoefficients(proj, mapping);
    SceneDepthDecode out;
    out.a = k.a;
    out.b = k.b;
    out.c = k.c;
    out.d = k.d;
    out.zBuffer = true;
    return out;
}

bool canSampleZBufferInPlace() { return glTextureBarrier != nullptr; }

SceneDepthSource sceneDepthSource(FrameBuilder& frame, const ViewInfo& view) {
    if (canSampleZBufferInPlace()) {
        const Target z = frame.sceneZBuffer();
        if (z.valid()) {
            const HostDepth how = frame.sceneZBufferMapping();
            DepthMapping mapping;
            mapping.clipZeroToOne = how.clipDepthZeroToOne;
            mapping.rangeNear = how.depthRangeNear;
            mapping.rangeFar = how.depthRangeFar;
            if (validDepthMapping(view.proj, mapping)) return {z, SceneDepthDecode::ofZBuffer(view.proj, mapping)};
        }
    }
    return {frame.sceneDepth(), SceneDepthDecode::linear()};
}

void sceneDepthBarrier(const SceneDepthDecode& decode) {
    if (decode.zBuffer && glTextureBarrier) glTextureBarrier();
}

glm::ivec2 viewOriginInDepth(int w, int h, const ViewInfo& view) {
    if (w == view.width && h == view.height) return glm::ivec2(0);
    return glm::ivec2(view.x, view.y);
}

SceneDepthDecode SceneDepthDecode::placedFor(const TextureRef& depth, const ViewInfo& view, bool intoSceneColor) const {
    SceneDepthDecode out = *this;
    out.texel = viewOriginInDepth(depth.width, depth.height, view);
    out.viewSize = glm::ivec2(view.width, view.height);
    out.drawOrigin = intoSceneColor ? glm::ivec2(view.x, view.y) : glm::ivec2(0);
    out.depthSize = glm::ivec2(depth.width, depth.height);
    return out;
}

void SceneDepthUniforms::locate(uint32_t program) {
    if (program == 0) return;  // a build that failed: nothing to look up (0 is no program)
    coeffs = glGetUniformLocation(program, "uDepthCoeffs");
    window = glGetUniformLocation(program, "uDepthWindow");
    drawOrigin = glGetUniformLocation(program, "uDrawOrigin");
    uv = glGetUniformLocation(program, "uDepthUv");
}

void setSceneDepthDecode(const SceneDepthUniforms& at, const SceneDepthDecode& decode) {
    glUniform4f(at.coeffs, decode.a, decode.b, decode.c, decode.d);
    glUniform4i(at.window, decode.texel.x, decode.texel.y, decode.viewSize.x, decode.viewSize.y);
    glUniform2i(at.drawOrigin, decode.drawOrigin.x, decode.drawOrigin.y);
    if (at.uv >= 0 && decode.depthSize.x > 0 && decode.depthSize.y > 0) {
        // Worked out here once, not per fragment: a CPU rasteriser does not hoist uniform-only
        // arithmetic out of the fragment shader.
        const glm::vec2 inv = 1.0f / glm::vec2(decode.depthSize);
        const glm::vec2 offset = glm::vec2(decode.texel - decode.drawOrigin) * inv;
        glUniform4f(at.uv, offset.x, offset.y, inv.x, inv.y);
    }
}

}  // namespace fx
