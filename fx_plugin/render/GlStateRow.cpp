#include "GlStateRow.h"

#include <cstdint>
#include <initializer_list>

#include "render/PrivateGl.h"

namespace fx {
namespace pinnedgl {
namespace {

GLuint asUint(double v) { return static_cast<GLuint>(static_cast<int64_t>(v)); }
GLboolean asBool(double v) { return v != 0.0 ? GL_TRUE : GL_FALSE; }

void getPair(GLenum a, GLenum b, Value* out) {
    GLfloat x = 0.0f, y = 0.0f;
    glGetFloatv(a, &x);
    glGetFloatv(b, &y);
    out->v[0] = x;
    out->v[1] = y;
}
void getIntsOf(std::initializer_list<GLenum> names, Value* out) {
    int i = 0;
    for (GLenum n : names) {
        GLint v = 0;
        glGetIntegerv(n, &v);
        out->v[i++] = v;
    }
}

}  // namespace

// ---- readers ----------------------------------------------------------------------------------

void getEnable(const Row& r, Value* out) { out->v[0] = glIsEnabled(r.pname) ? 1.0 : 0.0; }
void getEnablei(const Row& r, Value* out) { out->v[0] = glIsEnabledi(r.pname, r.index) ? 1.0 : 0.0; }
void getInts(const Row& r, Value* out) {
    GLint v[4] = {};
    glGetIntegerv(r.pname, v);
    for (int i = 0; i < 4; ++i) out->v[i] = v[i];
}
void getFloats(const Row& r, Value* out) {
    GLfloat v[4] = {};
    glGetFloatv(r.pname, v);
    for (int i = 0; i < 4; ++i) out->v[i] = v[i];
}
void getBool(const Row& r, Value* out) {
    GLboolean b = GL_FALSE;
    glGetBooleanv(r.pname, &b);
    out->v[0] = b ? 1.0 : 0.0;
}
void getPolygonFace(const Row& r, Value* out) {  // GL_POLYGON_MODE: front, back
    GLint v[2] = {};
    glGetIntegerv(GL_POLYGON_MODE, v);
    out->v[0] = v[r.index];
}
void getColorMaski(const Row& r, Value* out) {
    GLboolean b[4] = {};
    glGetBooleani_v(GL_COLOR_WRITEMASK, r.index, b);
    for (int i = 0; i < 4; ++i) out->v[i] = b[i] ? 1.0 : 0.0;
}
void getPolygonOffset(const Row&, Value* out) { getPair(GL_POLYGON_OFFSET_FACTOR, GL_POLYGON_OFFSET_UNITS, out); }
void getSampleCoverage(const Row&, Value* out) { getPair(GL_SAMPLE_COVERAGE_VALUE, GL_SAMPLE_COVERAGE_INVERT, out); }
void getAlphaFunc(const Row&, Value* out) {
    GLint func = 0;
    GLfloat ref = 0.0f;
    glGetIntegerv(GL_ALPHA_TEST_FUNC, &func);
    glGetFloatv(GL_ALPHA_TEST_REF, &ref);
    out->v[0] = func;
    out->v[1] = ref;
}
void getSampleMask(const Row& r, Value* out) {
    GLint v = 0;
    glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, r.index, &v);
    out->v[0] = v;
}
void getDepthRange(const Row&, Value* out) {
    GLdouble v[2] = {};
    glGetDoublev(GL_DEPTH_RANGE, v);
    out->v[0] = v[0];
    out->v[1] = v[1];
}
void getStencilFunc(const Row& r, Value* out) {
    if (r.index == GL_FRONT) getIntsOf({GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK}, out);
    else getIntsOf({GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK}, out);
}
void getStencilOp(const Row& r, Value* out) {
    if (r.index == GL_FRONT) getIntsOf({GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS}, out);
    else getIntsOf({GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS}, out);
}
void getClipControl(const Row&, Value* out) { getIntsOf({GL_CLIP_ORIGIN, GL_CLIP_DEPTH_MODE}, out); }
void getTexture2D(const Row& r, Value* out) {
    glActiveTexture(GL_TEXTURE0 + r.index);
    getIntsOf({GL_TEXTURE_BINDING_2D}, out);
}
void getSampler(const Row& r, Value* out) {
    glActiveTexture(GL_TEXTURE0 + r.index);
    getIntsOf({GL_SAMPLER_BINDING}, out);
}
void getLodBias(const Row& r, Value* out) {
    glActiveTexture(GL_TEXTURE0 + r.index);
    GLfloat v = 0.0f;
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &v);
    out->v[0] = v;
}

void getBlendFunc(const Row&, Value* out) {
    getIntsOf({GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA}, out);
}
void getBlendEquation(const Row&, Value* out) { getIntsOf({GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA}, out); }

// ---- writers ----------------------------------------------------------------------------------

void setEnable(const Row& r, const Value& v) { v.v[0] != 0.0 ? glEnable(r.pname) : glDisable(r.pname); }
void setEnablei(const Row& r, const Value& v) {
    v.v[0] != 0.0 ? glEnablei(r.pname, r.index) : glDisablei(r.pname, r.index);
}
void setPixelStore(const Row& r, const Value& v) { glPixelStorei(r.pname, GLint(v.v[0])); }
void setPixelTransfer(const Row& r, const Value& v) { glPixelTransferf(r.pname, GLfloat(v.v[0])); }
void setPolygonMode(const Row&, const Value& v) { glPolygonMode(GL_FRONT_AND_BACK, GLenum(v.v[0])); }
void setPolygonFace(const Row& r, const Value& v) {
    glPolygonMode(r.index == 0 ? GL_FRONT : GL_BACK, GLenum(v.v[0]));
}
void setPolygonOffset(const Row&, const Value& v) { glPolygonOffset(GLfloat(v.v[0]), GLfloat(v.v[1])); }
void setLogicOp(const Row&, const Value& v) { glLogicOp(GLenum(v.v[0])); }
void setSampleCoverage(const Row&, const Value& v) { glSampleCoverage(GLfloat(v.v[0]), asBool(v.v[1])); }
void setSampleMask(const Row& r, const Value& v) { glSampleMaski(r.index, asUint(v.v[0])); }
void setStencilFunc(const Row& r, const Value& v) {
    glStencilFuncSeparate(r.index, GLenum(v.v[0]), GLint(v.v[1]), asUint(v.v[2]));
}
void setStencilOp(const Row& r, const Value& v) {
    glStencilOpSeparate(r.index, GLenum(v.v[0]), GLenum(v.v[1]), GLenum(v.v[2]));
}
void setStencilMask(const Row& r, const Value& v) { glStencilMaskSeparate(r.index, asUint(v.v[0])); }
void setColorMaski(const Row& r, const Value& v) {
    glColorMaski(r.index, asBool(v.v[0]), asBool(v.v[1]), asBool(v.v[2]), asBool(v.v[3]));
}
void setBlendFunc(const Row&, const Value& v) {
    glBlendFuncSeparate(GLenum(v.v[0]), GLenum(v.v[1]), GLenum(v.v[2]), GLenum(v.v[3]));
}
void setBlendEquation(const Row&, const Value& v) { glBlendEquationSeparate(GLenum(v.v[0]), GLenum(v.v[1])); }
void setBlendColor(const Row&, const Value& v) {
    glBlendColor(GLfloat(v.v[0]), GLfloat(v.v[1]), GLfloat(v.v[2]), GLfloat(v.v[3]));
}
void setClearColor(const Row&, const Value& v) {
    glClearColor(GLfloat(v.v[0]), GLfloat(v.v[1]), GLfloat(v.v[2]), GLfloat(v.v[3]));
}
void setDepthFunc(const Row&, const Value& v) { glDepthFunc(GLenum(v.v[0])); }
void setDepthMask(const Row&, const Value& v) { glDepthMask(asBool(v.v[0])); }
void setDepthRange(const Row&, const Value& v) { glDepthRange(v.v[0], v.v[1]); }
void setClipControl(const Row&, const Value& v) {
    // The rows are built once per process; a later host may hand out no glClipControl.
    if (glClipControl) glClipControl(GLenum(v.v[0]), GLenum(v.v[1]));
}
void setProvokingVertex(const Row&, const Value& v) { glProvokingVertex(GLenum(v.v[0])); }
void setPointSize(const Row&, const Value& v) { glPointSize(GLfloat(v.v[0])); }
void setLineWidth(const Row&, const Value& v) { glLineWidth(GLfloat(v.v[0])); }
void setRestartIndex(const Row&, const Value& v) { glPrimitiveRestartIndex(asUint(v.v[0])); }
void setHint(const Row& r, const Value& v) { glHint(r.pname, GLenum(v.v[0])); }
void setClampColor(const Row& r, const Value& v) { glClampColor(r.pname, GLenum(v.v[0])); }
void setAlphaFunc(const Row&, const Value& v) { glAlphaFunc(GLenum(v.v[0]), GLfloat(v.v[1])); }
void setViewport(const Row&, const Value& v) { glViewport(GLint(v.v[0]), GLint(v.v[1]), GLsizei(v.v[2]), GLsizei(v.v[3])); }
void setScissor(const Row&, const Value& v) { glScissor(GLint(v.v[0]), GLint(v.v[1]), GLsizei(v.v[2]), GLsizei(v.v[3])); }
void setProgram(const Row&, const Value& v) { glUseProgram(asUint(v.v[0])); }
void setVertexArray(const Row&, const Value& v) { glBindVertexArray(asUint(v.v[0])); }
void setBuffer(const Row& r, const Value& v) { glBindBuffer(r.index, asUint(v.v[0])); }
void setFramebuffer(const Row& r, const Value& v) { glBindFramebuffer(r.index, asUint(v.v[0])); }
void setActiveTexture(const Row&, const Value& v) { glActiveTexture(GLenum(v.v[0])); }
void setTexture2D(const Row& r, const Value& v) {
    glActiveTexture(GL_TEXTURE0 + r.index);
    glBindTexture(GL_TEXTURE_2D, asUint(v.v[0]));
}
void setSampler(const Row& r, const Value& v) { glBindSampler(r.index, asUint(v.v[0])); }
void setLodBias(const Row& r, const Value& v) {
    glActiveTexture(GL_TEXTURE0 + r.index);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, GLfloat(v.v[0]));
}

Value val(double a, double b, double c, double d) {
    Value v;
    v.v[0] = a;
    v.v[1] = b;
    v.v[2] = c;
    v.v[3] = d;
    return v;
}

}  // namespace pinnedgl
}  // namespace fx
