#pragma once
// Shared by PoisonedHostState.cpp, HostStateReadback.cpp and FogTest.cpp: the tests' glad is 3.3
// core, so the compatibility-profile enums are defined and its entry points fetched here by hand.
#include <glad/gl.h>

#include <utility>

namespace fxtest {
namespace poisoned_host_gl {

constexpr GLenum kAlphaTest = 0x0BC0, kAlphaTestFunc = 0x0BC1, kAlphaTestRef = 0x0BC2;
constexpr GLenum kPolygonStipple = 0x0B42, kClipPlane0 = 0x3000;
constexpr GLenum kClampVertexColor = 0x891A, kClampFragmentColor = 0x891B;
constexpr GLenum kMapColor = 0x0D10, kMapStencil = 0x0D11, kIndexShift = 0x0D12, kIndexOffset = 0x0D13;
constexpr GLenum kRedScale = 0x0D14, kRedBias = 0x0D15, kGreenScale = 0x0D18, kGreenBias = 0x0D19;
constexpr GLenum kBlueScale = 0x0D1A, kBlueBias = 0x0D1B, kAlphaScale = 0x0D1C, kAlphaBias = 0x0D1D;
constexpr GLenum kDepthScale = 0x0D1E, kDepthBias = 0x0D1F;
constexpr GLenum kTextureFilterControl = 0x8500, kTextureLodBias = 0x8501;
constexpr GLenum kPrimitiveRestartFixedIndex = 0x8D69;
// GL 4.3's shader storage buffers and 4.2's image units (the tiled path binds both).
constexpr GLenum kShaderStorageBuffer = 0x90D2, kShaderStorageBufferBinding = 0x90D3;
constexpr GLenum kShaderStorageBufferStart = 0x90D4, kShaderStorageBufferSize = 0x90D5;
constexpr GLenum kImageBindingName = 0x8F3A, kImageBindingAccess = 0x8F3E, kImageBindingFormat = 0x906E;
constexpr GLenum kReadWrite = 0x88BA, kRgba8 = 0x8058;
constexpr int kUnits = 6;  // GlStateGuard::kTextureUnits

// The pixel-store parameters, by the names the poisons and the readback give them.
inline const std::pair<const char*, GLenum> kPixelStores[] = {
    {"unpack swap bytes", GL_UNPACK_SWAP_BYTES}, {"unpack lsb first", GL_UNPACK_LSB_FIRST},
    {"unpack alignment", GL_UNPACK_ALIGNMENT},   {"unpack row length", GL_UNPACK_ROW_LENGTH},
    {"unpack skip rows", GL_UNPACK_SKIP_ROWS},   {"unpack skip pixels", GL_UNPACK_SKIP_PIXELS},
    {"unpack image height", GL_UNPACK_IMAGE_HEIGHT}, {"unpack skip images", GL_UNPACK_SKIP_IMAGES},
    {"pack swap bytes", GL_PACK_SWAP_BYTES},     {"pack lsb first", GL_PACK_LSB_FIRST},
    {"pack alignment", GL_PACK_ALIGNMENT},       {"pack row length", GL_PACK_ROW_LENGTH},
    {"pack skip rows", GL_PACK_SKIP_ROWS},       {"pack skip pixels", GL_PACK_SKIP_PIXELS},
    {"pack image height", GL_PACK_IMAGE_HEIGHT}, {"pack skip images", GL_PACK_SKIP_IMAGES}};

struct Compat {
    void (*alphaFunc)(GLenum, GLfloat) = nullptr;
    void (*pixelTransferf)(GLenum, GLfloat) = nullptr;
    void (*texEnvf)(GLenum, GLenum, GLfloat) = nullptr;
    void (*getTexEnvfv)(GLenum, GLenum, GLfloat*) = nullptr;
    void (*clipPlane)(GLenum, const GLdouble*) = nullptr;
    void (*polygonStipple)(const GLubyte*) = nullptr;
    void (*clipControl)(GLenum, GLenum) = nullptr;
    void (*bindImageTexture)(GLuint, GLuint, GLint, GLboolean, GLint, GLenum, GLenum) = nullptr;
    void (*getInteger64i_v)(GLenum, GLuint, GLint64*) = nullptr;
    // The fixed-function fog and immediate-mode drawing of FogTest.cpp.
    void (*fogi)(GLenum, GLint) = nullptr;
    void (*fogf)(GLenum, GLfloat) = nullptr;
    void (*fogfv)(GLenum, const GLfloat*) = nullptr;
    void (*matrixMode)(GLenum) = nullptr;
    void (*loadMatrixf)(const GLfloat*) = nullptr;
    void (*begin)(GLenum) = nullptr;
    void (*end)() = nullptr;
    void (*vertex3f)(GLfloat, GLfloat, GLfloat) = nullptr;
    void (*color4f)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
};

template <typename F>
inline void load(F* fn, const char* name) {
    *fn = reinterpret_cast<F>(osMesaProcAddress()(name));
}

inline const Compat& compat() {
    static const Compat c = [] {
        Compat k;
        load(&k.alphaFunc, "glAlphaFunc");
        load(&k.pixelTransferf, "glPixelTransferf");
        load(&k.texEnvf, "glTexEnvf");
        load(&k.getTexEnvfv, "glGetTexEnvfv");
        load(&k.clipPlane, "glClipPlane");
        load(&k.polygonStipple, "glPolygonStipple");
        load(&k.clipControl, "glClipControl");
        load(&k.bindImageTexture, "glBindImageTexture");
        load(&k.getInteger64i_v, "glGetInteger64i_v");
        load(&k.fogi, "glFogi");
        load(&k.fogf, "glFogf");
        load(&k.fogfv, "glFogfv");
        load(&k.matrixMode, "glMatrixMode");
        load(&k.loadMatrixf, "glLoadMatrixf");
        load(&k.begin, "glBegin");
        load(&k.end, "glEnd");
        load(&k.vertex3f, "glVertex3f");
        load(&k.color4f, "glColor4f");
        return k;
    }();
    return c;
}

inline int glVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}


}  // namespace poisoned_host_gl
}  // namespace fxtest
