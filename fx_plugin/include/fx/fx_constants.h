/* CubeFx C API: fxBool, the error codes and every FX_* enumeration; included by fx/fx.h, which
 * holds the contract (include that one). C89, no other include. */
#ifndef FX_FX_CONSTANTS_H
#define FX_FX_CONSTANTS_H

typedef int fxBool; /* 0 = false, anything else = true */

/* ---- error codes (the same numbers as fx::ErrorCode; fxErrorCodeName gives the name) ------- */
enum {
    FX_ERROR_NONE = 0,
    FX_ERROR_FILE_NOT_FOUND, FX_ERROR_EMPTY_FILE, FX_ERROR_SYNTAX_ERROR, FX_ERROR_TOO_DEEP,
    FX_ERROR_WRONG_TYPE, FX_ERROR_UNKNOWN_KEY, FX_ERROR_MISSING_KEY, FX_ERROR_OUT_OF_RANGE,
    FX_ERROR_NOT_FINITE, FX_ERROR_NEGATIVE_COUNT, FX_ERROR_INVALID_ENUM, FX_ERROR_DUPLICATE_NAME,
    FX_ERROR_DUPLICATE_KEY, FX_ERROR_FILE_TOO_LARGE, FX_ERROR_TOO_MANY_ERRORS,
    FX_ERROR_VERSION_MISMATCH, FX_ERROR_NULL_ARGUMENT, FX_ERROR_INDEX_OUT_OF_RANGE,
    FX_ERROR_INVALID_VALUE, FX_ERROR_INVALID_VIEW, FX_ERROR_SIZE_MISMATCH, FX_ERROR_NO_GL_CONTEXT,
    FX_ERROR_SHADER_BUILD, FX_ERROR_RESOURCE_MISSING,
    /* API 2.0 */
    FX_ERROR_BAD_DESCRIPTOR,     /* a struct's size is one the library does not know */
    FX_ERROR_UNSUPPORTED_DEPTH,  /* a depth texture format or source the plugin cannot read */
    FX_ERROR_INVALID_HANDLE,     /* a plugin handle that is not live: destroyed, or never created */
    FX_ERROR_COUNT_
};

enum { FX_LOG_INFO = 0, FX_LOG_WARNING = 1, FX_LOG_ERROR = 2 };
enum { FX_SURFACE_ASPHALT = 0, FX_SURFACE_KERB, FX_SURFACE_GRASS, FX_SURFACE_GRAVEL, FX_SURFACE_SAND };
enum { FX_TECHNIQUE_FROM_REACTION = 0, FX_TECHNIQUE_HARD, FX_TECHNIQUE_SOFT, FX_TECHNIQUE_SPHERICAL,
       FX_TECHNIQUE_MEGA };
enum { FX_SHAPE_TRIMMED = 0, FX_SHAPE_QUAD = 1 };
enum { FX_EDGES_DEPTH_AWARE = 0, FX_EDGES_MIXED_RESOLUTION = 1 };
enum { FX_FADE_CLASSIFICATION_OFF = 0, FX_FADE_CLASSIFICATION_ON = 1 };
enum { FX_TILING_AUTO = 0, FX_TILING_OFF = 1, FX_TILING_ON = 2 }; /* API 2.4: fxRenderOptions.tiling */
enum { FX_FORMAT_RGBA8 = 0, FX_FORMAT_RGBA16F, FX_FORMAT_R32F, FX_FORMAT_RG32F,
       FX_FORMAT_DEPTH /* API 2.1: fxTextureRef of fxFrameBuilder.sceneZBuffer only */ };
/* How the host's z-buffer is ordered: standard (near = 0, LEQUAL) or reversed (near = 1, GEQUAL). */
enum { FX_DEPTH_STANDARD = 0, FX_DEPTH_REVERSED_Z = 1 };
enum { FX_RIGHT_HANDED = 0, FX_LEFT_HANDED = 1 };
/* API 2.1: which world axis points up in the host's world (fxPluginDesc.upAxis). */
enum { FX_UP_Y = 0, FX_UP_Z = 1 };
/* Where fxRenderView finds the scene depth. */
enum {
    FX_DEPTH_FROM_FRAMEBUFFER = 0, /* the depth attachment of the framebuffer bound for drawing
                                      (the default framebuffer too), copied only when a pass needs it */
    FX_DEPTH_FROM_TEXTURE = 1,     /* depthTexture: GL_DEPTH_COMPONENT16/24/32F or DEPTH24_STENCIL8 */
    FX_DEPTH_FROM_LINEAR = 2,      /* depthTexture: GL_R32F linear view depth in metres (the 1.x form);
                                      another format: FX_ERROR_UNSUPPORTED_DEPTH */
    FX_DEPTH_FROM_NOTHING = 3      /* no scene depth: particles are neither z-tested nor faded */
};
/* API 2.1: fxViewDesc.fogMode, as GL_LINEAR / GL_EXP / GL_EXP2 fixed-function fog. */
enum { FX_FOG_OFF = 0, FX_FOG_LINEAR = 1, FX_FOG_EXP = 2, FX_FOG_EXP2 = 3 };
enum { FX_KEY_NUMBER = 0, FX_KEY_INTEGER, FX_KEY_BOOL, FX_KEY_CHOICE, FX_KEY_CHOICE_LIST,
       FX_KEY_NUMBER_RANGE, FX_KEY_INTEGER_PAIR, FX_KEY_COLOR_RAMP, FX_KEY_NAME };

#endif /* FX_FX_CONSTANTS_H */
