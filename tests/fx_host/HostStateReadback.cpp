// PoisonedHostState.h: reading back, comparing and resetting the state the poisons touch.
#include <cstdio>

#include "FxTestHost.h"
#include "PoisonedHostGl.h"
#include "PoisonedHostState.h"

namespace fxtest {

namespace phg = poisoned_host_gl;

HostStateReadback readHostState() {
    HostStateReadback r;
    auto ints = [&](const char* name, GLenum e, int n) {
        GLint v[4] = {};
        glGetIntegerv(e, v);
        r[name].assign(v, v + n);
    };
    auto floats = [&](const char* name, GLenum e, int n) {
        GLfloat v[4] = {};
        glGetFloatv(e, v);
        r[name].assign(v, v + n);
    };
    const GLenum enables[] = {GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_POLYGON_OFFSET_FILL,
                              GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_LINE_SMOOTH,
                              GL_PROGRAM_POINT_SIZE, GL_CULL_FACE, GL_MULTISAMPLE, GL_SAMPLE_COVERAGE,
                              GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_MASK,
                              GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DEPTH_TEST,
                              GL_FRAMEBUFFER_SRGB, GL_DITHER, GL_COLOR_LOGIC_OP};
    for (GLenum e : enables) r["enable 0x" + std::to_string(e)] = {double(glIsEnabled(e))};
    if (phg::glVersion() >= 43) r["enable fixed index"] = {double(glIsEnabled(phg::kPrimitiveRestartFixedIndex))};
    GLint clipDistances = 0, drawBuffers = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    for (GLint i = 0; i < clipDistances; ++i) {
        r["clip distance " + std::to_string(i)] = {double(glIsEnabled(GLenum(GL_CLIP_DISTANCE0 + i)))};
    }
    for (GLint i = 0; i < drawBuffers; ++i) {
        GLboolean m[4] = {};
        glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), m);
        r["colour writemask " + std::to_string(i)] = {double(m[0]), double(m[1]), double(m[2]), double(m[3])};
        r["blend enable " + std::to_string(i)] = {double(glIsEnabledi(GL_BLEND, GLuint(i)))};
    }
    const std::pair<const char*, GLenum> singles[] = {
        {"active texture", GL_ACTIVE_TEXTURE}, {"program", GL_CURRENT_PROGRAM}, {"vertex array", GL_VERTEX_ARRAY_BINDING},
        {"array buffer", GL_ARRAY_BUFFER_BINDING}, {"draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING},
        {"read framebuffer", GL_READ_FRAMEBUFFER_BINDING}, {"pack buffer", GL_PIXEL_PACK_BUFFER_BINDING},
        {"unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING}, {"clamp read colour", GL_CLAMP_READ_COLOR},
        {"primitive restart index", GL_PRIMITIVE_RESTART_INDEX}, {"provoking vertex", GL_PROVOKING_VERTEX},
        {"cull face mode", GL_CULL_FACE_MODE}, {"front face", GL_FRONT_FACE},
        {"derivative hint", GL_FRAGMENT_SHADER_DERIVATIVE_HINT}, {"stencil func", GL_STENCIL_FUNC},
        {"stencil ref", GL_STENCIL_REF}, {"stencil value mask", GL_STENCIL_VALUE_MASK},
        {"stencil fail", GL_STENCIL_FAIL}, {"stencil zfail", GL_STENCIL_PASS_DEPTH_FAIL},
        {"stencil zpass", GL_STENCIL_PASS_DEPTH_PASS}, {"stencil writemask", GL_STENCIL_WRITEMASK},
        {"stencil back func", GL_STENCIL_BACK_FUNC}, {"stencil back ref", GL_STENCIL_BACK_REF},
        {"stencil back value mask", GL_STENCIL_BACK_VALUE_MASK}, {"stencil back fail", GL_STENCIL_BACK_FAIL},
        {"stencil back zfail", GL_STENCIL_BACK_PASS_DEPTH_FAIL}, {"stencil back zpass", GL_STENCIL_BACK_PASS_DEPTH_PASS},
        {"stencil back writemask", GL_STENCIL_BACK_WRITEMASK}, {"depth func", GL_DEPTH_FUNC},
        {"depth writemask", GL_DEPTH_WRITEMASK}, {"logic op", GL_LOGIC_OP_MODE},
        {"blend src rgb", GL_BLEND_SRC_RGB}, {"blend dst rgb", GL_BLEND_DST_RGB},
        {"blend src alpha", GL_BLEND_SRC_ALPHA}, {"blend dst alpha", GL_BLEND_DST_ALPHA},
        {"blend eq rgb", GL_BLEND_EQUATION_RGB}, {"blend eq alpha", GL_BLEND_EQUATION_ALPHA}};
    for (const auto& s : singles) ints(s.first, s.second, 1);
    for (const auto& s : phg::kPixelStores) ints(s.first, s.second, 1);
    ints("polygon mode", GL_POLYGON_MODE, 2);
    ints("viewport", GL_VIEWPORT, 4);
    ints("scissor box", GL_SCISSOR_BOX, 4);
    floats("polygon offset factor", GL_POLYGON_OFFSET_FACTOR, 1);
    floats("polygon offset units", GL_POLYGON_OFFSET_UNITS, 1);
    floats("line width", GL_LINE_WIDTH, 1);
    floats("point size", GL_POINT_SIZE, 1);
    floats("sample coverage value", GL_SAMPLE_COVERAGE_VALUE, 1);
    ints("sample coverage invert", GL_SAMPLE_COVERAGE_INVERT, 1);
    floats("depth range", GL_DEPTH_RANGE, 2);
    floats("blend colour", GL_BLEND_COLOR, 4);
    floats("clear colour", GL_COLOR_CLEAR_VALUE, 4);
    GLint mask = 0;
    glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
    r["sample mask value 0"] = {double(mask)};
    if (phg::glVersion() >= 43) {
        // The tiled path's bindings: shader storage buffers 0-5 (with their ranges) and the generic
        // one, image unit 0.
        ints("shader storage buffer", phg::kShaderStorageBufferBinding, 1);
        for (GLuint i = 0; i < 6; ++i) {
            GLint b = 0;
            GLint64 start = 0, size = 0;
            glGetIntegeri_v(phg::kShaderStorageBufferBinding, i, &b);
            phg::compat().getInteger64i_v(phg::kShaderStorageBufferStart, i, &start);
            phg::compat().getInteger64i_v(phg::kShaderStorageBufferSize, i, &size);
            r["shader storage buffer " + std::to_string(i)] = {double(b), double(start), double(size)};
        }
        GLint image[3] = {0, 0, 0};
        glGetIntegeri_v(phg::kImageBindingName, 0, &image[0]);
        glGetIntegeri_v(phg::kImageBindingAccess, 0, &image[1]);
        glGetIntegeri_v(phg::kImageBindingFormat, 0, &image[2]);
        r["image unit 0"] = {double(image[0]), double(image[1]), double(image[2])};
    }
    if (phg::compat().clipControl) {
        ints("clip origin", GL_CLIP_ORIGIN, 1);
        ints("clip depth mode", GL_CLIP_DEPTH_MODE, 1);
    }
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    const bool compatProfile = osMesaCompatibilityProfile();
    for (int u = 0; u < 8; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        ints(("texture unit " + std::to_string(u)).c_str(), GL_TEXTURE_BINDING_2D, 1);
        ints(("sampler unit " + std::to_string(u)).c_str(), GL_SAMPLER_BINDING, 1);
        if (compatProfile && u < phg::kUnits) {
            GLfloat bias = 0.0f;
            phg::compat().getTexEnvfv(phg::kTextureFilterControl, phg::kTextureLodBias, &bias);
            r["LOD bias unit " + std::to_string(u)] = {double(bias)};
        }
    }
    glActiveTexture(GLenum(active));
    if (compatProfile) {
        r["alpha test"] = {double(glIsEnabled(phg::kAlphaTest))};
        r["polygon stipple"] = {double(glIsEnabled(phg::kPolygonStipple))};
        ints("alpha func", phg::kAlphaTestFunc, 1);
        floats("alpha ref", phg::kAlphaTestRef, 1);
        ints("clamp fragment colour", phg::kClampFragmentColor, 1);
        ints("clamp vertex colour", phg::kClampVertexColor, 1);
        const GLenum transfers[] = {phg::kRedScale,  phg::kGreenScale, phg::kBlueScale, phg::kAlphaScale, phg::kDepthScale,
                                    phg::kRedBias,   phg::kGreenBias,  phg::kBlueBias,  phg::kAlphaBias,  phg::kDepthBias,
                                    phg::kMapColor,  phg::kMapStencil, phg::kIndexShift, phg::kIndexOffset};
        for (GLenum e : transfers) floats(("pixel transfer 0x" + std::to_string(e)).c_str(), e, 1);
    }
    return r;
}

std::string diffHostState(const HostStateReadback& before, const HostStateReadback& after) {
    std::string out;
    for (const auto& b : before) {
        const auto a = after.find(b.first);
        if (a == after.end() || a->second == b.second) continue;
        out += b.first + ":";
        for (double v : b.second) out += " " + std::to_string(v);
        out += " ->";
        for (double v : a->second) out += " " + std::to_string(v);
        out += "\n";
    }
    return out;
}

void resetHostState() {
    applyDefaultHostState();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (GLenum e : {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
                     GL_UNPACK_SKIP_PIXELS, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_PACK_SWAP_BYTES,
                     GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                     GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES}) {
        glPixelStorei(e, 0);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
    for (GLenum e : {GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_POLYGON_OFFSET_FILL,
                     GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_LINE_SMOOTH,
                     GL_PROGRAM_POINT_SIZE, GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                     GL_SAMPLE_MASK, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_FRAMEBUFFER_SRGB, GL_COLOR_LOGIC_OP}) {
        glDisable(e);
    }
    if (phg::glVersion() >= 43) {
        glDisable(phg::kPrimitiveRestartFixedIndex);
        for (GLuint i = 0; i < 4; ++i) glBindBufferBase(phg::kShaderStorageBuffer, i, 0);
        glBindBuffer(phg::kShaderStorageBuffer, 0);
        phg::compat().bindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, phg::kRgba8);
    }
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_DITHER);
    glPrimitiveRestartIndex(0);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    GLint clipDistances = 0, drawBuffers = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    for (GLint i = 0; i < clipDistances; ++i) glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    for (GLint i = 0; i < drawBuffers; ++i) {
        glDisablei(GL_BLEND, GLuint(i));
        glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    if (phg::compat().clipControl) phg::compat().clipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthRange(0.0, 1.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glSampleCoverage(1.0f, GL_FALSE);
    glSampleMaski(0, ~0u);
    glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE);
    glStencilFunc(GL_ALWAYS, 0, ~0u);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(~0u);
    glDepthMask(GL_TRUE);
    glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
    glLogicOp(GL_COPY);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    if (osMesaCompatibilityProfile()) {
        glDisable(phg::kAlphaTest);
        phg::compat().alphaFunc(GL_ALWAYS, 0.0f);
        glDisable(phg::kPolygonStipple);
        glDisable(phg::kClipPlane0);
        glClampColor(phg::kClampFragmentColor, GL_FIXED_ONLY);
        glClampColor(phg::kClampVertexColor, GL_TRUE);
        for (GLenum e : {phg::kRedScale, phg::kGreenScale, phg::kBlueScale, phg::kAlphaScale, phg::kDepthScale}) phg::compat().pixelTransferf(e, 1.0f);
        for (GLenum e : {phg::kRedBias, phg::kGreenBias, phg::kBlueBias, phg::kAlphaBias, phg::kDepthBias, phg::kMapColor, phg::kMapStencil, phg::kIndexShift,
                         phg::kIndexOffset}) {
            phg::compat().pixelTransferf(e, 0.0f);
        }
        for (int u = 0; u < phg::kUnits; ++u) {
            glActiveTexture(GLenum(GL_TEXTURE0 + u));
            phg::compat().texEnvf(phg::kTextureFilterControl, phg::kTextureLodBias, 0.0f);
        }
        glActiveTexture(GL_TEXTURE0);
    }
}

}  // namespace fxtest
