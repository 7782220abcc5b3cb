#include "GlStateGuard.h"

#include "render/PrivateGl.h"

namespace fx {
namespace {

int getInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

bool getBool(GLenum name) {
    GLboolean v = GL_FALSE;
    glGetBooleanv(name, &v);
    return v == GL_TRUE;
}

void setEnabled(GLenum cap, bool on) {
    if (on) {
        glEnable(cap);
    } else {
        glDisable(cap);
    }
}

}  // namespace

void bindTextureUnit(int unit, uint32_t texture, uint32_t sampler) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    glBindSampler(GLuint(unit), GLuint(sampler));
}

NearestSampler::~NearestSampler() {
    if (sampler_) glDeleteSamplers(1, &sampler_);
}

void NearestSampler::create() {
    if (sampler_) return;
    glGenSamplers(1, &sampler_);
    glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void NearestSampler::bindTexture(int unit, uint32_t texture) const { bindTextureUnit(unit, texture, sampler_); }

DebugGroup::DebugGroup(const char* name) : active_(FXGLAD_GL_KHR_debug != 0) {
    if (active_) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}

DebugGroup::~DebugGroup() {
    if (active_) glPopDebugGroup();
}

namespace {
constexpr GLenum kAlphaTest = 0x0BC0;  // GL_ALPHA_TEST: compatibility only, not in the core loader
}  // namespace

GlStateGuard::GlStateGuard() {
    State& s = saved_;
    // A compatibility context applies the fixed-function alpha test to shader output too, and a
    // legacy host may leave it on: Irrlicht 1.8 does (GL_GREATER 0) after a transparent material,
    // which discarded the linear-depth pass's alpha-0 fragments and with them every occlusion. It is
    // the one pre-shader per-fragment state the passes do not set themselves, so the guard turns it
    // off for the plugin's calls and back on after. (A core context has no GL_ALPHA_TEST.)
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if ((profile & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0 && glIsEnabled(kAlphaTest) == GL_TRUE) {
        s.alphaTest = true;
        glDisable(kAlphaTest);
    }
    s.program = getInt(GL_CURRENT_PROGRAM);
    s.vertexArray = getInt(GL_VERTEX_ARRAY_BINDING);
    s.arrayBuffer = getInt(GL_ARRAY_BUFFER_BINDING);
    s.activeTexture = getInt(GL_ACTIVE_TEXTURE);
    for (int i = 0; i < kTextureUnits; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        s.texture2D[i] = getInt(GL_TEXTURE_BINDING_2D);
        s.sampler[i] = getInt(GL_SAMPLER_BINDING);
    }
    glActiveTexture(GLenum(s.activeTexture));
    s.blend = glIsEnabled(GL_BLEND) == GL_TRUE;
    s.blendSrcRgb = getInt(GL_BLEND_SRC_RGB);
    s.blendDstRgb = getInt(GL_BLEND_DST_RGB);
    s.blendSrcAlpha = getInt(GL_BLEND_SRC_ALPHA);
    s.blendDstAlpha = getInt(GL_BLEND_DST_ALPHA);
    s.blendEqRgb = getInt(GL_BLEND_EQUATION_RGB);
    s.blendEqAlpha = getInt(GL_BLEND_EQUATION_ALPHA);
    s.depthTest = glIsEnabled(GL_DEPTH_TEST) == GL_TRUE;
    s.depthMask = getBool(GL_DEPTH_WRITEMASK);
    s.depthFunc = getInt(GL_DEPTH_FUNC);
    s.cullFace = glIsEnabled(GL_CULL_FACE) == GL_TRUE;
    s.stencilTest = glIsEnabled(GL_STENCIL_TEST) == GL_TRUE;
    s.scissorTest = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    glGetIntegerv(GL_SCISSOR_BOX, s.scissorBox);
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    for (int i = 0; i < 4; ++i) s.colorMask[i] = mask[i] == GL_TRUE;
    glGetFloatv(GL_COLOR_CLEAR_VALUE, s.clearColor);
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    s.drawFramebuffer = getInt(GL_DRAW_FRAMEBUFFER_BINDING);
    s.readFramebuffer = getInt(GL_READ_FRAMEBUFFER_BINDING);
    s.unpackBuffer = getInt(GL_PIXEL_UNPACK_BUFFER_BINDING);
    s.unpackAlignment = getInt(GL_UNPACK_ALIGNMENT);
    s.unpackRowLength = getInt(GL_UNPACK_ROW_LENGTH);
    s.unpackSkipRows = getInt(GL_UNPACK_SKIP_ROWS);
    s.unpackSkipPixels = getInt(GL_UNPACK_SKIP_PIXELS);
    s.unpackImageHeight = getInt(GL_UNPACK_IMAGE_HEIGHT);
    s.unpackSkipImages = getInt(GL_UNPACK_SKIP_IMAGES);
    s.packBuffer = getInt(GL_PIXEL_PACK_BUFFER_BINDING);
    s.packAlignment = getInt(GL_PACK_ALIGNMENT);
    s.packRowLength = getInt(GL_PACK_ROW_LENGTH);
    s.packSkipRows = getInt(GL_PACK_SKIP_ROWS);
    s.packSkipPixels = getInt(GL_PACK_SKIP_PIXELS);
}

GlStateGuard::~GlStateGuard() {
    const State& s = saved_;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(s.drawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(s.readFramebuffer));
    glViewport(s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]);
    glUseProgram(GLuint(s.program));
    glBindVertexArray(GLuint(s.vertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(s.arrayBuffer));
    for (int i = 0; i < kTextureUnits; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, GLuint(s.texture2D[i]));
        glBindSampler(GLuint(i), GLuint(s.sampler[i]));
    }
    glActiveTexture(GLenum(s.activeTexture));
    setEnabled(GL_BLEND, s.blend);
    glBlendFuncSeparate(GLenum(s.blendSrcRgb), GLenum(s.blendDstRgb), GLenum(s.blendSrcAlpha),
                        GLenum(s.blendDstAlpha));
    glBlendEquationSeparate(GLenum(s.blendEqRgb), GLenum(s.blendEqAlpha));
    setEnabled(GL_DEPTH_TEST, s.depthTest);
    glDepthMask(s.depthMask ? GL_TRUE : GL_FALSE);
    glDepthFunc(GLenum(s.depthFunc));
    setEnabled(GL_CULL_FACE, s.cullFace);
    setEnabled(GL_STENCIL_TEST, s.stencilTest);
    setEnabled(GL_SCISSOR_TEST, s.scissorTest);
    if (s.alphaTest) glEnable(kAlphaTest);
    glScissor(s.scissorBox[0], s.scissorBox[1], s.scissorBox[2], s.scissorBox[3]);
    glColorMask(s.colorMask[0], s.colorMask[1], s.colorMask[2], s.colorMask[3]);
    glClearColor(s.clearColor[0], s.clearColor[1], s.clearColor[2], s.clearColor[3]);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(s.unpackBuffer));
    glPixelStorei(GL_UNPACK_ALIGNMENT, s.unpackAlignment);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, s.unpackRowLength);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, s.unpackSkipRows);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, s.unpackSkipPixels);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, s.unpackImageHeight);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, s.unpackSkipImages);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(s.packBuffer));
    glPixelStorei(GL_PACK_ALIGNMENT, s.packAlignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, s.packRowLength);
    glPixelStorei(GL_PACK_SKIP_ROWS, s.packSkipRows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, s.packSkipPixels);
}

}  // namespace fx
