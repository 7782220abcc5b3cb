/* CubeFx API 2: the plugin's C boundary. The only symbols libcubefx.so exports are the three C
 * functions at the end of this file; everything else is reached through the function table that
 * fxGetApi returns, in the shape of Quake III's refexport/refimport: the host hands in a table of
 * callbacks (fxHostCallbacks), the plugin hands back a table of functions (fxApi).
 *
 * Contract (every guarantee, in one place):
 *  - C89 and later (C++98 and later), no C++ type crosses: opaque handles, plain structs, function
 *    pointers with a user pointer, integers for enums and error codes. A host built with any
 *    compiler or standard library that follows the platform's C calling convention can use it; so
 *    can a C host. (The C++ layer over it, fx/Plugin.h, needs C++11.)
 *  - Versions: FX_API_VERSION is MAJOR << 16 | MINOR. fxGetApi(v) returns the table for MAJOR 2
 *    when v's MINOR is at most the library's; else null. A MINOR release appends functions to
 *    fxApi and fields to the end of structs; it changes no existing one.
 *  - Every struct the host fills begins with `size` (sizeof the struct as the host compiled it:
 *    FX_DESC_INIT does this) and is read up to that size; a field the host leaves 0 takes the
 *    default its comment states. A size the library does not know (0, smaller than the 2.0
 *    struct, or larger than its own) is refused with FX_ERROR_BAD_DESCRIPTOR.
 *  - Every struct the plugin writes for the host begins with `size` too, set by the host
 *    (FX_DESC_INIT), and the plugin writes no byte at or past out->size: the entries that take
 *    them (since API 2.1: stats2, checkParticles2, reactionStats2, reactionKey2,
 *    declareShadowPasses2; getRenderOptions) fill the fields of the host's size and leave the
 *    rest of a newer library's struct out, so a struct can grow in a MINOR release. Those entries
 *    refuse a size they do not know, as above, and write nothing. getRenderOptions alone, a 2.0
 *    entry, fills the 2.0 fields for any size it does not know (what 2.0 did, whatever the size).
 *  - Deprecated: the output structs of API 2.0 (fxStats, fxParticleCheck, fxReactionStats,
 *    fxReactionKeyInfo, fxSmokeShadow, fxFadeClassCounts) carry no size, so they never grow; the
 *    2.0 entries that write them stay in the table and write exactly that layout, so a host built
 *    against the 2.0 header runs unchanged. A new host uses the entries named ...2 above. The
 *    option setters of 2.0 stay too: setParticleShape/particleShape are
 *    fxRenderOptions.particleShape now; the quarter-res edge entries are accepted and have no
 *    effect since 2.1, the fade classification entries none since 2.4. Each deprecated entry is
 *    marked where the table lists it.
 *  - A refused call changes nothing, returns a named FX_ERROR_* code and is logged through the
 *    host's log callback ("fx: error[Code] function: what was expected"), at most a few times
 *    per (function, code), then counted in fxStats2.apiErrors. Where no host can be reached
 *    safely (create refusing fxPluginDesc's size or version, fxHostCallbacks' size or a null log;
 *    a null or dead handle) the same line goes to stderr instead, with the same limit.
 *  - Every number is an input with a stated range (the comment at its field or function; the
 *    FX_MAX_* limits below); a value outside it is refused (FX_ERROR_INVALID_VALUE, or
 *    FX_ERROR_INVALID_VIEW for fxViewDesc) unless its comment says it is clamped.
 *  - Handles: every function checks its fxPlugin* against the set of live plugins (those create
 *    returned and destroy has not yet taken) before it reads through it. A destroyed handle, a
 *    second destroy, or a pointer create never returned is refused with FX_ERROR_INVALID_HANDLE
 *    (a null one with FX_ERROR_NULL_ARGUMENT; destroy(NULL) does nothing, like free(NULL)) and
 *    nothing is done. Not detected: a destroyed handle whose address a later create happens to
 *    get again (it names the new plugin), and a call racing destroy on another thread.
 *  - (GL) calls check, after their arguments and before any other GL call, that a context is
 *    current (glGetString answers) and that the host's getProcAddress gave every entry point the
 *    plugin's drawing calls; else FX_ERROR_NO_GL_CONTEXT, naming the missing functions, and
 *    nothing is marked failed: the next call with a context goes ahead. Optional features degrade with one warning line: KHR_debug groups (glPush/
 *    PopDebugGroup) and clip control (glClipControl). The entry points are loaded once for all
 *    live plugins; after the last one is destroyed, the next plugin loads them again.
 *  - No call leaves a GL error pending that it caused. Checking a depthTexture name of another
 *    target takes back the GL_INVALID_OPERATION the check raises; a context keeps only its first
 *    error, so an error the host itself left pending before that call is the one taken.
 *  - Strings the plugin returns are copied into the caller's buffer (snprintf style: the return
 *    value is the length without the terminating 0; a buffer too small, or null with 0, gets a
 *    truncated or no copy and the caller retries with length + 1). Strings the plugin hands to
 *    callbacks are valid only during the callback.
 *  - Threading and GL: one thread at a time; functions marked (GL) need the host's GL context
 *    current on the calling thread. The plugin starts no threads; it may hand pieces of a view's
 *    CPU work to the host's job system (fxHostCallbacks.parallelFor, API 2.2) while it prepares
 *    or draws the view, and every piece has returned before the call or pass does. Around every (GL) call and every pass it runs, the plugin
 *    sets every GL state its output depends on and restores every state it touched, in core and
 *    compatibility contexts (fx_plugin/README.md lists them).
 *  - Matrices are 16 floats, column-major (OpenGL's layout; glm::value_ptr, Irrlicht's
 *    matrix4::pointer()).
 */
#ifndef FX_FX_H
#define FX_FX_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(FX_BUILDING_PLUGIN)
#define FX_C_API __attribute__((visibility("default")))
#else
#define FX_C_API
#endif

#define FX_API_VERSION_MAJOR 2
#define FX_API_VERSION_MINOR 4
#define FX_API_VERSION ((uint32_t)((FX_API_VERSION_MAJOR << 16) | FX_API_VERSION_MINOR))

/* The ranges of numeric inputs (see each field and function). */
#define FX_MAX_TIME_STEP 3600.0f /* continueReaction's dt: 0 .. one hour of simulated time */
#define FX_MAX_VIEW_SIZE 16384   /* fxViewDesc width and height: 1 .. 16384 pixels */
#define FX_MAX_WORLD_COORDINATE 1e9f /* fireReaction's point: each coordinate within +-1e9 m */

/* Zero-initialises a descriptor and sets its size: `fxViewDesc v = FX_DESC_INIT(fxViewDesc);`
 * Valid in every C from C89 and every C++ from C++98, under -pedantic-errors. Every struct it is
 * meant for begins with `uint32_t size`, so the expansion can be chosen per language:
 *  - C99 and later: the designated initialiser {.size = sizeof(T)};
 *  - C89/C90 (no designated initialisers): the positional {sizeof(T)}, which sets the first
 *    field, size, and zero-fills the rest. GCC's and Clang's -Wextra warn about it
 *    (-Wmissing-field-initializers); a C89 host that builds with -Wextra adds
 *    -Wno-missing-field-initializers;
 *  - C++ (designated initialisers only from C++20): a value-initialised T with its size set
 *    (fxDescInit_, below), which no warning flags. */
#if defined(__cplusplus)
#define FX_DESC_INIT(T) fxDescInit_<T>()
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L
#define FX_DESC_INIT(T) {.size = sizeof(T)}
#else
#define FX_DESC_INIT(T) {sizeof(T)}
#endif

#include "fx_constants.h" /* fxBool, the error codes and every FX_* enumeration */

typedef struct fxPlugin fxPlugin; /* opaque */

/* ---- what the host gives ------------------------------------------------------------------ */

typedef struct fxWheelContact {
    float position[3]; /* contact patch centre, world, metres */
    float velocity[3]; /* hub velocity, world, m/s */
    float slip;        /* 0 rolling .. 1 full lock/spin; may exceed 1; NaN reads as 0 */
    int surface;       /* FX_SURFACE_*; another value reads as asphalt */
    fxBool grounded;
    fxBool rear;
} fxWheelContact;

/* The host's services. Required: getProcAddress and log. Optional, each on its own (null = the
 * default given): wheelCount without wheel, or wheel without wheelCount, means no wheels. */
typedef struct fxHostCallbacks {
    uint32_t size;
    void* user; /* handed back to every callback */
    /* GL entry points of the host's context (null before one exists). */
    void* (*getProcAddress)(void* user, const char* name);
    void (*log)(void* user, int level, const char* message);
    int (*wheelCount)(void* user);   /* null: no wheels; clamped to 0 .. 16 */
    void (*wheel)(void* user, int index, fxWheelContact* out);        /* null: no wheels */
    void (*wind)(void* user, float out[3]);                           /* null: still air */
    void (*collisionPoint)(void* user, float out[3]);                 /* null: the origin */
    /* API 2.2 (a 2.0/2.1 size leaves it null). The host's job system: call task(data, i) once
     * for every i in [0, count), on any threads, any number at once, and return when every call
     * has returned. A task touches no GL and calls nothing of the host's or the plugin's; the
     * plugin asks while preparing a view (declarePasses, renderView), while its particle pass
     * runs (the instance copy) and in continueReaction (the particles' step), for work of
     * thousands of particles, in at most 64 pieces, and its results do not depend on how they
     * are run. null: in order on the calling thread. */
    void (*parallelFor)(void* user, uint32_t count, void (*task)(void* data, uint32_t index), void* data);
} fxHostCallbacks;

typedef struct fxPluginDesc {
    uint32_t size;
    uint32_t apiVersion;           /* 0 = FX_API_VERSION of these headers */
    const fxHostCallbacks* host;   /* required; copied, its user pointer must outlive the plugin */
    const char* shaderDir;         /* null/"" = embedded shaders; a folder = live shader edits */
    const char* dataDir;           /* null/"" = embedded smoke atlas */
    uint64_t seed;                 /* any value; 0 = the plugin's default */
    /* API 2.1 (a 2.0 host's smaller size reads as FX_UP_Y). Which axis of the host's world points
     * up: FX_UP_Y (0) or FX_UP_Z (a right-handed Z-up world: X east, Y north, Z up). The plugin's
     * own world stays Y-up (reaction files, emission directions, gravity and wind fields are
     * written Y-up); every world vector it receives is turned into it on the way in (wheel
     * positions and velocities, wind, collision point, fireReaction's point, the sun's toSun,
     * each view's view matrix and eye: view' = view B) and the shadow's worldToShadow is turned
     * back on the way out, so a Z-up host gets the picture a Y-up host of the same scene gets.
     * It is the plugin's, not a view's: the simulation (continueReaction, which has no view)
     * runs in that basis before any view is declared, and every view sees the same particles. */
    int upAxis;
} fxPluginDesc;

/* One view. Matrices as the host draws its scene with them; `handedness` says which way its
 * camera looks (right-handed: down -Z, OpenGL; left-handed: down +Z, Direct3D-style engines). */
typedef struct fxViewDesc {
    uint32_t size;
    const char* name;      /* pass names and debug groups; null = "" */
    float view[16];        /* every element finite (else FX_ERROR_INVALID_VIEW) */
    float proj[16];        /* every element finite */
    float eye[3];          /* finite */
    float nearPlane;       /* > 0, finite */
    float farPlane;        /* > nearPlane, finite: with an infinite projection matrix (which the
                              plugin linearises exactly), the distance past which depth reads as
                              "nothing drawn", e.g. the far end of the scene */
    /* near/far and proj: the scene depth is decoded from proj (with depthOrder, clip control and
     * depth range) alone, so near/far that differ from proj's planes never move a fade. They bound
     * the smoke instead: particles wholly nearer than nearPlane or farther than farPlane are not
     * drawn, render.near_fade fades from nearPlane, spherical particles are cut at it, and their
     * depth-tested quads are held between 1.01 nearPlane and 0.99 farPlane. Planes wider than
     * proj's cost nothing but culling (the GPU clips at proj's); a nearPlane beyond proj's near or
     * a farPlane short of proj's far removes smoke the scene still shows. A host that computes its
     * planes per frame (scene graphs fitting them to the scene's bounds) hands in each frame the
     * planes that frame's proj was built with. */
    int width, height;     /* pixels of the colour target, 1 .. FX_MAX_VIEW_SIZE */
    int depthOrder;        /* FX_DEPTH_STANDARD / FX_DEPTH_REVERSED_Z: how the z-buffer is ordered */
    int handedness;        /* FX_RIGHT_HANDED (0) or FX_LEFT_HANDED */
    /* fxRenderView only: */
    int depthSource;       /* FX_DEPTH_FROM_* ; 0 = the bound framebuffer's depth attachment */
    uint32_t depthTexture; /* GL_TEXTURE_2D name for FROM_TEXTURE / FROM_LINEAR, of the view's size;
                              another name or target: FX_ERROR_UNSUPPORTED_DEPTH */
    fxBool clipDepthZeroToOne; /* the host drew with glClipControl(..., GL_ZERO_TO_ONE) */
    float depthRangeNear, depthRangeFar; /* glDepthRange the host drew with, each in [0, 1], not
                                            equal; both 0 = [0, 1] */
    /* API 2.1 (a 2.0 host's smaller size reads as 0): a view anywhere in the framebuffer
     * (split screen, a picture in a picture).
     * declarePasses: the view is the rectangle (viewportX, viewportY, width, height) of
     * sceneColor, which is targetWidth x targetHeight (0 = width x height, the 2.0 contract);
     * the host's bindForDraw(sceneColor) sets that rectangle as the viewport. sceneZBuffer is
     * sceneColor's own depth, so it is targetWidth x targetHeight too.
     * fxRenderView: the viewport the host set at the call places the view (its size must be
     * width x height); viewportX/Y and targetWidth/Height are not read.
     * Scene depth addressing (both paths): a depth texture of width x height holds the view
     * alone, from its own (0, 0) (the plugin's copy of a bound framebuffer's depth is always
     * that: it copies the view's rectangle); a depth texture of any other size holds the whole
     * framebuffer, the view at the viewport's origin (the host's z-buffer of a split screen). */
    int viewportX, viewportY;
    int targetWidth, targetHeight;
    /* fxRenderView only (API 2.1): 1 = the scissor test the host has enabled at the call clips
     * the smoke too (a split screen scissored to each view, a letterbox); 0 = the plugin ignores
     * the host's scissor state, as in 2.0 (a scissor left on by accident does not cut the smoke).
     * On the frame-graph path a scissor the host's bindForDraw(sceneColor) sets always holds. */
    fxBool clipToScissor;
    /* API 2.1 (a 2.0 host's smaller size leaves them out: no fog, every particle).
     * The host's fog (fx::Fog in fx/Types.h has the formulas): the smoke is fogged as GL's
     * fixed-function fog fogs geometry at the same eye-space distance |z_eye|. */
    int fogMode;            /* FX_FOG_*; 0 = off */
    float fogColor[3];      /* linear RGB */
    float fogStart, fogEnd; /* FX_FOG_LINEAR, metres; end != start */
    float fogDensity;       /* FX_FOG_EXP / EXP2, 1/m, >= 0 */
    /* Only particles whose view distance is in [sliceMinDistance, sliceMaxDistance) are drawn
     * (fx::DistanceSlice): draw the smoke in slices around the host's own blended geometry.
     * sliceMaxDistance 0 = no upper bound; both 0 = every particle. */
    float sliceMinDistance, sliceMaxDistance;
} fxViewDesc;

/* Written by setRenderOptions, read back by getRenderOptions. Defaults (every field 0): each
 * reaction's own technique at full resolution, trimmed particles. */
typedef struct fxRenderOptions {
    uint32_t size;
    int techniqueOverride;  /* FX_TECHNIQUE_* (0 .. FX_TECHNIQUE_MEGA), 0 = each reaction's own */
    fxBool quarterRes;      /* 0 = full resolution; else particles into a half x half target
                             * where that is cheaper (quarterResAlways) */
    fxBool bilinearUpsample; /* quarterRes's composite with plain bilinear (comparison only); 0 = depth-aware */
    /* API 2.1 (a 2.0 host's smaller size leaves the shape as it is: setRenderOptions sets the
     * fields above only). How hard and soft billboards are rasterised (fx::ParticleShape):
     * FX_SHAPE_TRIMMED (0) a tight polygon per atlas frame, FX_SHAPE_QUAD the full quad. */
    int particleShape;
    /* API 2.1: with quarterRes, 0 = per view, quarter res only where the smoke's overdraw pays
     * (a frame builder's view declares both paths' passes and the first to run chooses, since
     * 2026-11-28); else all views at it, as 2.0. A 2.0 host's size leaves it (0 unless set). */
    fxBool quarterResAlways;
    /* API 2.3 (a 2.0-2.2 size leaves it): 1 = hard, soft and spherical particles (lit too) shaded
     * per 16 px tile by a compute shader where the context has one; 0 = as tiling says. API 2.4 (older
     * sizes leave it): tiling, FX_TILING_AUTO (0) tiled on a GPU, not a software rasterizer. */
    fxBool tiled;
    int tiling;
} fxRenderOptions;

typedef struct fxSceneLight {
    uint32_t size;
    float toSun[3];       /* finite, not zero (the plugin normalises it) */
    float sunColor[3];    /* finite, each >= 0 */
    float ambient[3];     /* finite, each >= 0 */
} fxSceneLight;

/* ---- the host's frame graph (fxApi.declarePasses; engines without one use fxRenderView) ---- */

typedef struct fxTargetDesc {
    uint32_t size;
    float scale;          /* relative to the view when width/height are 0; 0 = 1 */
    int width, height;    /* absolute size; 0 = relative */
    int format;           /* FX_FORMAT_*, 0 = RGBA8 */
    fxBool nearestFilter; /* 0 = linear filtering */
    fxBool depth;         /* a depth buffer of its own */
} fxTargetDesc;

typedef struct fxTextureRef {
    uint32_t name;        /* GL_TEXTURE_2D name; 0 = none */
    int format;           /* FX_FORMAT_* */
    int width, height;
} fxTextureRef;

/* Valid only while a pass runs. */
typedef struct fxPassContext {
    uint32_t size;
    void* user;
    void (*bindForDraw)(void* user, uint32_t target);
    void (*texture)(void* user, uint32_t target, int attachment, fxTextureRef* out);
    int (*width)(void* user, uint32_t target);
    int (*height)(void* user, uint32_t target);
} fxPassContext;

/* A pass the plugin declares. The host calls run() when the pass executes (or never, when it is
 * culled) and release() exactly once when it drops the pass, after it ran or was culled. */
typedef struct fxPassCallback {
    void* user;
    void (*run)(void* user, const fxPassContext* ctx);
    void (*release)(void* user);
} fxPassCallback;

typedef struct fxFrameBuilder {
    uint32_t size;
    void* user;
    uint32_t (*sceneColor)(void* user);
    uint32_t (*sceneDepth)(void* user);  /* linear R32F view depth, metres (see fx/HostAdapter.h) */
    uint32_t (*createTarget)(void* user, const char* name, const fxTargetDesc* desc);
    void (*addPass)(void* user, const char* name, const uint32_t* reads, int readCount,
                    const uint32_t* writes, int writeCount, fxPassCallback callback);
    /* API 2.1 (a 2.0 host's smaller size leaves them out: the plugin then reads sceneDepth).
     * The z-buffer sceneColor draws on, holding the opaque scene: a target a pass lists among
     * its reads to sample it (fxPassContext.texture gives the depth texture, FX_FORMAT_DEPTH),
     * and how it was drawn. The plugin samples it in place, with depth writes off and a texture
     * barrier first, where the context has glTextureBarrier (GL 4.5, ARB_texture_barrier), and
     * never writes it; then the host needs no linear depth at all. Null or 0 = none offered.
     * Offer it where its precision holds (reversed-Z float: about 6e-8 t; standard 24-bit:
     * 3e-8 t^2 / near, see fx/HostAdapter.h). */
    uint32_t (*sceneZBuffer)(void* user);
    fxBool zBufferClipZeroToOne;            /* drawn under glClipControl(..., GL_ZERO_TO_ONE) */
    float zBufferRangeNear, zBufferRangeFar; /* glDepthRange it was drawn with; both 0 = [0, 1] */
} fxFrameBuilder;

/* ---- what the plugin gives back ------------------------------------------------------------ */

typedef struct fxDiagnostic {
    int code;             /* FX_ERROR_* */
    const char* file;
    int line, column;     /* 1-based, 0 = unknown */
    const char* key;      /* dotted path, "" when none */
    const char* message;
} fxDiagnostic;

/* Receives each problem of a call (load, reload, prepare); may be null to ignore them. */
typedef struct fxDiagnosticSink {
    void* user;
    void (*report)(void* user, const fxDiagnostic* diagnostic);
} fxDiagnosticSink;

/* The structs below are written by the plugin. Those with a `size` (API 2.1) are filled up to the
 * size the host set (the contract above); a refused call writes nothing into them. */

typedef struct fxStats2 {
    uint32_t size;
    int reactions;
    int particlesAlive;
    int particleCapacity; /* pool slots over every reaction */
    int particlesDrawn;   /* in the last declared view, after culling */
    int reloads;          /* successful hot reloads */
    int reloadErrors;     /* refused hot reloads (the old set kept) */
    int apiErrors;        /* calls refused with an FX_ERROR_* code since create */
} fxStats2;

typedef struct fxParticleCheck2 {
    uint32_t size;
    int alive, capacity;
    int nonFinite;        /* NaN or infinite values in live particles' state; 0 when healthy */
} fxParticleCheck2;

typedef struct fxReactionStats2 {
    uint32_t size;
    char name[72];        /* the reaction's name */
    char technique[16];   /* "hard", "soft", "spherical", "mega" or "stateless" */
    int alive;            /* live particles now */
    uint64_t emitted;     /* particles that entered its pool since it was loaded */
    uint64_t dropped;     /* particles due while its pool was full */
} fxReactionStats2;

/* One key of the reaction schema; the strings live as long as the plugin. */
typedef struct fxReactionKeyInfo2 {
    uint32_t size;
    const char* key;
    int kind;             /* FX_KEY_* */
    double min, max;
    const char* const* choices;
    int choiceCount;
    const char* unit;
    const char* help;
} fxReactionKeyInfo2;

typedef struct fxSmokeShadow2 {
    uint32_t size;
    uint32_t opacity;       /* frame-graph target; 0 = no smoke this frame */
    float worldToShadow[16];
} fxSmokeShadow2;

#include "fx_deprecated.h" /* the 2.0 output structs the deprecated entries below write */

/* The plugin's functions. Returns of type int are FX_ERROR_* unless stated; fxBool returns are
 * success. Calls on a null plugin return FX_ERROR_NULL_ARGUMENT / 0 / "" and do nothing; on a
 * dead one (see "Handles" above) FX_ERROR_INVALID_HANDLE / 0 / "". Indices (reaction, file,
 * key) are 0 .. count - 1, else FX_ERROR_INDEX_OUT_OF_RANGE (and 0 or "" where the return is a
 * count or a string). Out-pointers of stats and queries are required: null is refused. */
typedef struct fxApi {
    uint32_t size;
    uint32_t version;  /* the library's FX_API_VERSION */

    /* Creation (no GL) and destruction (GL: deletes the plugin's GL objects). On failure null,
     * *error (may be null) set and the reason logged through desc->host when its size, version
     * and host table were accepted, else on stderr (a refused descriptor is not read further). */
    fxPlugin* (*create)(const fxPluginDesc* desc, int* error);
    void (*destroy)(fxPlugin* plugin);

    /* Reactions: a .yaml file or a folder of them. No GL. */
    fxBool (*loadReactions)(fxPlugin* p, const char* path, const fxDiagnosticSink* out);
    fxBool (*pollHotReload)(fxPlugin* p, const fxDiagnosticSink* out);
    /* length: 0 .. 4 MiB (else FX_ERROR_FILE_TOO_LARGE, nothing read). */
    fxBool (*loadReactionsFromText)(fxPlugin* p, const char* file, const char* text, size_t length,
                                    const fxDiagnosticSink* out);
    int (*reactionCount)(const fxPlugin* p);
    size_t (*reactionName)(const fxPlugin* p, int index, char* buffer, size_t capacity);
    size_t (*reactionFile)(const fxPlugin* p, int index, char* buffer, size_t capacity);
    int (*reactionFileCount)(const fxPlugin* p);
    size_t (*reactionFileAt)(const fxPlugin* p, int fileIndex, char* buffer, size_t capacity);
    size_t (*reactionValue)(const fxPlugin* p, int index, const char* key, char* buffer, size_t capacity);
    int (*reactionParticlesAlive)(const fxPlugin* p, int index);
    int (*reactionStats)(const fxPlugin* p, int index, fxReactionStats* out); /* deprecated: reactionStats2 */
    int (*reactionKeyCount)(const fxPlugin* p);
    int (*reactionKey)(const fxPlugin* p, int keyIndex, fxReactionKeyInfo* out); /* deprecated: reactionKey2 */

    /* Simulation. dt: 0 .. FX_MAX_TIME_STEP seconds (NaN, infinite, negative or larger:
     * FX_ERROR_INVALID_VALUE). collision may be null; *collision is clamped to 0 .. 1 (NaN reads as
     * 0). fireReaction's point: finite, each coordinate within
     * +-FX_MAX_WORLD_COORDINATE metres. */
    int (*continueReaction)(fxPlugin* p, int index, float dt, float* collision);
    int (*fireReaction)(fxPlugin* p, const char* name, const float point[3]);

    /* Options. An int outside its enum (FX_SHAPE_*, FX_EDGES_*, FX_FADE_CLASSIFICATION_*,
     * FX_TECHNIQUE_*) is FX_ERROR_INVALID_VALUE; an fxBool is any int. Values out of an
     * fxSceneLight's ranges are FX_ERROR_INVALID_VALUE. setRenderOptions sets every field of the
     * host's size at once (a refused field sets none); getRenderOptions: see the contract above. */
    int (*setRenderOptions)(fxPlugin* p, const fxRenderOptions* options);
    void (*getRenderOptions)(const fxPlugin* p, fxRenderOptions* out);
    /* Deprecated since API 2.1 (kept for 2.0 hosts): fxRenderOptions.particleShape. */
    int (*setParticleShape)(fxPlugin* p, int shape);
    int (*particleShape)(const fxPlugin* p);
    /* Deprecated, no effect: mixed-resolution edges (since 2.1) and fade classification (since
     * 2.4: on a GPU its depth pyramid and masks cost more than the fetches they skipped, see
     * Plugin.h's FadeClassification). Each still refuses a value outside its enum and returns
     * the value set. fadeClassCounts writes counted 0 and every count 0. */
    int (*setQuarterResEdges)(fxPlugin* p, int edges);
    int (*quarterResEdges)(const fxPlugin* p);
    int (*setFadeClassification)(fxPlugin* p, int mode);
    int (*fadeClassification)(const fxPlugin* p);
    int (*setFadeClassCounting)(fxPlugin* p, fxBool on);
    void (*fadeClassCounts)(const fxPlugin* p, fxFadeClassCounts* out);
    /* Scene state, not an option: the sun and ambient light the smoke is lit by. */
    int (*setSceneLight)(fxPlugin* p, const fxSceneLight* light);
    void (*clearSceneLight)(fxPlugin* p);

    /* GL. */
    fxBool (*prepareGl)(fxPlugin* p, const fxDiagnosticSink* out);                 /* (GL) */
    fxBool (*pollShaderReload)(fxPlugin* p, const fxDiagnosticSink* out);          /* (GL) */
    /* The frame-graph path: declares this view's passes (none when no particle is visible). */
    int (*declarePasses)(fxPlugin* p, const fxViewDesc* view, const fxFrameBuilder* frame); /* (GL) */
    /* Deprecated: declareShadowPasses2. */
    int (*declareShadowPasses)(fxPlugin* p, const fxViewDesc* view, const fxFrameBuilder* frame,
                               fxSmokeShadow* out);                                 /* (GL) */
    /* The immediate path: after the opaque scene and the sky, draws the smoke into the
     * framebuffer bound for drawing (GL_DRAW_FRAMEBUFFER, the default one included) over
     * view->width x view->height from the origin of the viewport the host set (anywhere in the
     * framebuffer since API 2.1; with view->clipToScissor, a scissor test the host enabled
     * clips the smoke too).
     * Scene depth from view->depthSource. The
     * plugin owns and pools its transient targets (resized with the view, freed by destroy;
     * a frame without visible particles allocates and copies nothing). */
    int (*renderView)(fxPlugin* p, const fxViewDesc* view);                         /* (GL) */

    /* Counters. Deprecated: stats2, checkParticles2. */
    void (*stats)(const fxPlugin* p, fxStats* out);
    void (*checkParticles)(const fxPlugin* p, fxParticleCheck* out);

    /* API 2.1: the output structs with a size. out is required (null: FX_ERROR_NULL_ARGUMENT)
     * and its size one the library knows (else FX_ERROR_BAD_DESCRIPTOR); a refused call writes
     * nothing into it. */
    int (*stats2)(const fxPlugin* p, fxStats2* out);
    int (*checkParticles2)(const fxPlugin* p, fxParticleCheck2* out);
    /* A bad index: FX_ERROR_INDEX_OUT_OF_RANGE, nothing written (reactionStats, 2.0, cleared its
     * struct instead). */
    int (*reactionStats2)(const fxPlugin* p, int index, fxReactionStats2* out);
    int (*reactionKey2)(const fxPlugin* p, int keyIndex, fxReactionKeyInfo2* out);
    /* On FX_ERROR_NONE, out's opacity is 0 when there is no smoke this frame. */
    int (*declareShadowPasses2)(fxPlugin* p, const fxViewDesc* view, const fxFrameBuilder* frame,
                                fxSmokeShadow2* out);                                 /* (GL) */
} fxApi;

/* The library's FX_API_VERSION. No GL, no plugin, any thread. */
FX_C_API uint32_t fxApiVersion(void);
/* The function table for `version` (FX_API_VERSION of the host's headers), or null when the
 * library cannot serve it (another MAJOR, or a newer MINOR than its own). */
FX_C_API const fxApi* fxGetApi(uint32_t version);
/* "FileNotFound", "BadDescriptor", ...; "Unknown" outside the codes. */
FX_C_API const char* fxErrorCodeName(int code);

#ifdef __cplusplus
}

/* FX_DESC_INIT's C++ form: every field zero, size = sizeof(T). */
template <typename T>
inline T fxDescInit_() {
    T desc = T();
    desc.size = sizeof(T);
    return desc;
}
#endif

#endif /* FX_FX_H */
