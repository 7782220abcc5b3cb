/* A careless and hostile host written in C99 against fx/fx.h alone, compiled as C, with an OSMesa
 * 3.3 core context of its own: every call of the table survives it. fxHostileHostCheck() returns
 * the number of failed checks and writes what failed (and a few figures) into `report`;
 * HostileHostTest.cpp runs it, in the normal and the sanitizer build. The classes:
 *   1. refusals that touch nothing they refused (garbage descriptors);
 *   2. every number is an input (a sweep of each numeric parameter of the table);
 *   3. dead handles (use after destroy, double destroy, a foreign pointer);
 *   4. nothing silent, nothing left behind (depth formats, texture names, no context, counts);
 *   5. a checked loader (getProcAddress returns NULL for each function in turn).
 * After every refused call with a context current, glGetError must say GL_NO_ERROR. */
#include <GL/osmesa.h>

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fx/fx.h>

#define WIDTH 160
#define HEIGHT 120
#define MAX_NAMES 2048

#ifndef GL_R32F
#define GL_R32F 0x822E
#endif
#ifndef GL_RED
#define GL_RED 0x1903
#endif
#ifndef GL_TEXTURE_3D
#define GL_TEXTURE_3D 0x806F
#endif
#ifndef GL_DEPTH_COMPONENT24
#define GL_DEPTH_COMPONENT24 0x81A6
#endif

/* The few GL entry points the host itself needs. */
static struct {
    GLenum (*GetError)(void);
    void (*ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf);
    void (*Clear)(GLbitfield);
    void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
    void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    void (*GenTextures)(GLsizei, GLuint*);
    void (*DeleteTextures)(GLsizei, const GLuint*);
    void (*BindTexture)(GLenum, GLuint);
    void (*TexImage2D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*);
    void (*TexImage3D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*);
} gl;

static int loadGl(void) {
    OSMESAproc proc;
#define LOAD(f) (proc = OSMesaGetProcAddress("gl" #f), memcpy(&gl.f, &proc, sizeof proc), proc != NULL)
    return LOAD(GetError) && LOAD(ClearColor) && LOAD(Clear) && LOAD(Viewport) && LOAD(ReadPixels) &&
           LOAD(GenTextures) && LOAD(DeleteTextures) && LOAD(BindTexture) && LOAD(TexImage2D) && LOAD(TexImage3D);
#undef LOAD
}

/* ---- the host ----------------------------------------------------------------------------- */

typedef struct Host {
    int errors, warnings;
    char lastError[1024], lastWarning[1024];
    /* getProcAddress: NULL for `nullName`, or for every name in `nullSet` when nullSetOn. */
    const char* nullName;
    int nullSetOn;
    /* Every name asked for while `recording`. */
    int recording, nameCount;
    char* names[MAX_NAMES];
    int nullSet[MAX_NAMES];
} Host;

static Host g_host;

static void* hostProc(void* user, const char* name) {
    Host* h = (Host*)user;
    OSMESAproc f;
    void* p;
    int i;
    if (h->recording) {
        for (i = 0; i < h->nameCount && strcmp(h->names[i], name) != 0; ++i) {
        }
        if (i == h->nameCount && h->nameCount < MAX_NAMES) {
            h->names[h->nameCount] = (char*)malloc(strlen(name) + 1);
            if (h->names[h->nameCount]) strcpy(h->names[h->nameCount++], name);
        }
    }
    if (h->nullName && strcmp(h->nullName, name) == 0) return NULL;
    if (h->nullSetOn) {
        for (i = 0; i < h->nameCount; ++i)
            if (h->nullSet[i] && strcmp(h->names[i], name) == 0) return NULL;
    }
    f = OSMesaGetProcAddress(name);
    memcpy(&p, &f, sizeof p);
    return p;
}

static void hostLog(void* user, int level, const char* message) {
    Host* h = (Host*)user;
    if (level == FX_LOG_ERROR) {
        ++h->errors;
        snprintf(h->lastError, sizeof h->lastError, "%s", message);
    } else if (level == FX_LOG_WARNING) {
        ++h->warnings;
        snprintf(h->lastWarning, sizeof h->lastWarning, "%s", message);
    }
}

static int hostWheelCount(void* user) {
    (void)user;
    return 1;
}

static void hostWheel(void* user, int index, fxWheelContact* out) {
    (void)user;
    (void)index;
    memset(out, 0, sizeof *out);
    out->slip = 1.0f;
    out->surface = FX_SURFACE_ASPHALT;
    out->grounded = 1;
    out->rear = 1;
}

/* ---- a frame graph that records (declarePasses) -------------------------------------------- */

static uint32_t fgColor(void* u) {
    (void)u;
    return 1;
}
static uint32_t fgDepth(void* u) {
    (void)u;
    return 2;
}
static uint32_t fgCreate(void* u, const char* name, const fxTargetDesc* d) {
    (void)name;
    (void)d;
    return 100 + (uint32_t)++*(int*)u;
}
static void fgAdd(void* u, const char* name, const uint32_t* r, int rc, const uint32_t* w, int wc, fxPassCallback cb) {
    (void)u;
    (void)name;
    (void)r;
    (void)rc;
    (void)w;
    (void)wc;
    if (cb.release) cb.release(cb.user);  /* culled: never run */
}
/* The recording frame builder; the targets it creates are counted in *targets. */
static fxFrameBuilder recordingFrame(int* targets) {
    fxFrameBuilder frame;
    memset(&frame, 0, sizeof frame);
    frame.size = sizeof frame;
    frame.user = targets;
    frame.sceneColor = fgColor;
    frame.sceneDepth = fgDepth;
    frame.createTarget = fgCreate;
    frame.addPass = fgAdd;
    return frame;
}

/* ---- camera --------------------------------------------------------------------------------- */

static void lookAt(const float eye[3], const float at[3], float m[16]) {
    float f[3], s[3], u[3], n;
    int i;
    for (i = 0; i < 3; ++i) f[i] = at[i] - eye[i];
    n = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= n;
    s[0] = -f[2];
    s[1] = 0.0f;
    s[2] = f[0];
    n = sqrtf(s[0] * s[0] + s[2] * s[2]);
    s[0] /= n;
    s[2] /= n;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    memset(m, 0, 16 * sizeof *m);
    for (i = 0; i < 3; ++i) {
        m[i * 4 + 0] = s[i];
        m[i * 4 + 1] = u[i];
        m[i * 4 + 2] = -f[i];
    }
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    m[15] = 1.0f;
}

static fxViewDesc goodView(void) {
    fxViewDesc v = FX_DESC_INIT(fxViewDesc);
    const float eye[3] = {2.6f, 1.0f, 3.6f}, at[3] = {0.0f, 0.6f, -0.5f};
    const float t = 1.0f / tanf(0.5f * 55.0f * 3.14159265f / 180.0f), zn = 0.1f, zf = 500.0f;
    v.name = "hostile";
    lookAt(eye, at, v.view);
    v.nearPlane = zn;
    v.farPlane = zf;
    memset(v.proj, 0, sizeof v.proj);
    v.proj[0] = t / ((float)WIDTH / HEIGHT);
    v.proj[5] = t;
    v.proj[10] = (zf + zn) / (zn - zf);
    v.proj[11] = -1.0f;
    v.proj[14] = 2.0f * zf * zn / (zn - zf);
    memcpy(v.eye, eye, sizeof v.eye);
    v.width = WIDTH;
    v.height = HEIGHT;
    return v;
}

/* ---- checks --------------------------------------------------------------------------------- */

typedef struct Run {
    char* report;
    int capacity, used, failed;
} Run;

static void fail(Run* r, int line, const char* what, double value) {
    ++r->failed;
    if (r->used < r->capacity)
        r->used += snprintf(r->report + r->used, (size_t)(r->capacity - r->used), "HostileHost.c:%d: %s (value %g)\n",
                            line, what, value);
}
#define CHECKV(cond, value)                          \
    do {                                             \
        if (!(cond)) fail(run, __LINE__, #cond, (double)(value)); \
    } while (0)
#define CHECK(cond) CHECKV(cond, 0)
/* No GL error pending after a call (the host's context is current). */
#define CHECK_GL(value) CHECKV(gl.GetError() == GL_NO_ERROR, value)

static void note(Run* r, const char* text) {
    if (r->used < r->capacity) r->used += snprintf(r->report + r->used, (size_t)(r->capacity - r->used), "%s\n", text);
}

static const float kFloats[] = {0.0f, -0.0f, 1e-45f, -1e-45f, FLT_MIN, 1e-38f, -1e-38f, 1e38f, -1e38f, FLT_MAX,
                                -FLT_MAX, 1.0f, -1.0f, 1e30f, 3600.0f, 3600.5f};
#define FLOAT_COUNT ((int)(sizeof kFloats / sizeof kFloats[0]))
static float specialFloat(int i) { /* kFloats, then +Inf, -Inf, NaN */
    if (i < FLOAT_COUNT) return kFloats[i];
    if (i == FLOAT_COUNT) return (float)INFINITY;
    if (i == FLOAT_COUNT + 1) return -(float)INFINITY;
    return (float)NAN;
}
#define SPECIAL_FLOATS (FLOAT_COUNT + 3)
static const int kInts[] = {0, 1, -1, 2, 3, 4, 5, 255, 256, 16384, 16385, INT_MIN, INT_MAX, INT_MIN + 1, INT_MAX - 1};
#define INT_COUNT ((int)(sizeof kInts / sizeof kInts[0]))

static int apiErrors(const fxApi* api, fxPlugin* p) {
    fxStats s;
    memset(&s, 0, sizeof s);
    api->stats(p, &s);
    return s.apiErrors;
}

static fxPlugin* makePlugin(const fxApi* api, int* error) {
    static fxHostCallbacks callbacks; /* copied by create; static so a test can point at it */
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    memset(&callbacks, 0, sizeof callbacks);
    callbacks.size = sizeof callbacks;
    callbacks.user = &g_host;
    callbacks.getProcAddress = hostProc;
    callbacks.log = hostLog;
    callbacks.wheelCount = hostWheelCount;
    callbacks.wheel = hostWheel;
    desc.host = &callbacks;
    return api->create(&desc, error);
}

static int changedPixels(const unsigned char* a, const unsigned char* b) {
    int i, n = 0;
    for (i = 0; i < WIDTH * HEIGHT * 4; i += 4) n += memcmp(a + i, b + i, 3) != 0;
    return n;
}

/* Clears the default framebuffer, draws the smoke with renderView, returns the pixels changed. */
static int drawSmoke(Run* run, const fxApi* api, fxPlugin* p, int* code) {
    static unsigned char before[WIDTH * HEIGHT * 4], after[WIDTH * HEIGHT * 4];
    fxViewDesc v = goodView();
    gl.Viewport(0, 0, WIDTH, HEIGHT);
    gl.ClearColor(0.45f, 0.55f, 0.7f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.ReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, before);
    *code = api->renderView(p, &v);
    gl.ReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, after);
    CHECK_GL(*code);
    return changedPixels(before, after);
}

/* ---- 1. refusals that touch nothing they refused -------------------------------------------- */

static void garbageDescriptors(Run* run, const fxApi* api) {
    unsigned char garbage[256];
    fxPluginDesc desc;
    fxHostCallbacks callbacks;
    int error = -1;
    const int logged = g_host.errors;
    memset(garbage, 0xAB, sizeof garbage);
    /* A descriptor of garbage (size 0xABABABAB, host pointer 0xABAB...): refused on its size;
     * reading desc->host would touch unmapped memory (ASan reports it; without ASan it crashes). */
    CHECK(api->create((const fxPluginDesc*)(const void*)garbage, &error) == NULL && error == FX_ERROR_BAD_DESCRIPTOR);
    /* The right size, a garbage version and host pointer: refused on the version, host not read. */
    memcpy(&desc, garbage, sizeof desc);
    desc.size = sizeof desc;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_VERSION_MISMATCH);
    /* A good descriptor pointing at a garbage callback table: refused on its size, log not called. */
    memcpy(&callbacks, garbage, sizeof callbacks);
    desc.apiVersion = 0;
    desc.host = &callbacks;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_BAD_DESCRIPTOR);
    /* Sizes at the edges, and a null error pointer. */
    desc.size = 0;
    CHECK(api->create(&desc, NULL) == NULL);
    desc.size = 0xFFFFFFFFu;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_BAD_DESCRIPTOR);
    CHECK(g_host.errors == logged); /* the host's log was never reached through garbage */
}

/* ---- 2. every number is an input ------------------------------------------------------------ */

static void sweepSimulation(Run* run, const fxApi* api, fxPlugin* p) {
    int i, before, refused = 0;
    const int count = api->reactionCount(p);
    fxParticleCheck check;
    char buffer[64];
    fxReactionStats rs;
    fxReactionKeyInfo key;
    before = apiErrors(api, p);
    for (i = 0; i < SPECIAL_FLOATS; ++i) {
        float f = specialFloat(i);
        const int valid = f >= 0.0f && f <= FX_MAX_TIME_STEP;
        const int code = api->continueReaction(p, 0, f, NULL);
        CHECKV(code == (valid ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), f);
        refused += !valid;
        /* The collision amount is clamped (NaN reads as 0): accepted. */
        CHECKV(api->continueReaction(p, 0, 1.0f / 60.0f, &f) == FX_ERROR_NONE, f);
    }
    api->checkParticles(p, &check);
    CHECK(check.nonFinite == 0 && check.alive <= check.capacity);
    for (i = 0; i < INT_COUNT; ++i) {
        const int n = kInts[i], valid = n >= 0 && n < count;
        const int keys = api->reactionKeyCount(p);
        CHECKV(api->continueReaction(p, n, 0.01f, NULL) == (valid ? FX_ERROR_NONE : FX_ERROR_INDEX_OUT_OF_RANGE), n);
        CHECKV(api->reactionStats(p, n, &rs) == (valid ? FX_ERROR_NONE : FX_ERROR_INDEX_OUT_OF_RANGE), n);
        CHECKV((api->reactionName(p, n, buffer, sizeof buffer) > 0) == valid, n);
        CHECKV((api->reactionFile(p, n, buffer, sizeof buffer) > 0) == valid, n);
        CHECKV((api->reactionValue(p, n, "render.technique", buffer, sizeof buffer) > 0) == valid, n);
        CHECKV(api->reactionParticlesAlive(p, n) >= 0, n);
        CHECKV((api->reactionFileAt(p, n, buffer, sizeof buffer) > 0) == (n >= 0 && n < api->reactionFileCount(p)), n);
        CHECKV(api->reactionKey(p, n, &key) == (n >= 0 && n < keys ? FX_ERROR_NONE : FX_ERROR_INDEX_OUT_OF_RANGE), n);
        refused += !valid * 6 + !(n >= 0 && n < api->reactionFileCount(p)) + !(n >= 0 && n < keys);
        CHECKV(api->setParticleShape(p, n) == (n >= 0 && n <= FX_SHAPE_QUAD ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), n);
        CHECKV(api->setQuarterResEdges(p, n) ==
                   (n >= 0 && n <= FX_EDGES_MIXED_RESOLUTION ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), n);
        CHECKV(api->setFadeClassification(p, n) ==
                   (n >= 0 && n <= FX_FADE_CLASSIFICATION_ON ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), n);
        CHECKV(api->setFadeClassCounting(p, n) == FX_ERROR_NONE, n);
        refused += !(n >= 0 && n <= 1) * 3;
        {
            fxRenderOptions o = FX_DESC_INIT(fxRenderOptions);
            o.techniqueOverride = n;
            o.quarterRes = n;
            o.bilinearUpsample = n;
            CHECKV(api->setRenderOptions(p, &o) ==
                       (n >= 0 && n <= FX_TECHNIQUE_MEGA ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), n);
            refused += !(n >= 0 && n <= FX_TECHNIQUE_MEGA);
        }
    }
    /* Back to the defaults the drawing checks expect. */
    api->setParticleShape(p, FX_SHAPE_TRIMMED);
    api->setQuarterResEdges(p, FX_EDGES_DEPTH_AWARE);
    api->setFadeClassification(p, FX_FADE_CLASSIFICATION_OFF);
    api->setFadeClassCounting(p, 0);
    {
        fxRenderOptions o = FX_DESC_INIT(fxRenderOptions);
        api->setRenderOptions(p, &o);
    }
    /* Capacities: 0 and 1 write nothing past the buffer; the length is still returned. */
    buffer[0] = 'x';
    CHECK(api->reactionName(p, 0, buffer, 0) > 0 && buffer[0] == 'x');
    CHECK(api->reactionName(p, 0, buffer, 1) > 0 && buffer[0] == '\0');
    /* A length past the limit is refused before a byte is read (text points at 2 bytes). */
    CHECK(!api->loadReactionsFromText(p, "huge.yaml", "a:", SIZE_MAX, NULL));
    CHECK(!api->loadReactionsFromText(p, "huge.yaml", "a:", (size_t)4 * 1024 * 1024 + 1, NULL));
    refused += 2;
    CHECK(api->reactionCount(p) == count);
    CHECKV(apiErrors(api, p) - before == refused, apiErrors(api, p) - before - refused);
}

static void sweepLightAndFire(Run* run, const fxApi* api, fxPlugin* p, fxPlugin* explosion) {
    int i, c;
    for (i = 0; i < SPECIAL_FLOATS; ++i) {
        const float f = specialFloat(i);
        const int finite = isfinite(f);
        for (c = 0; c < 3; ++c) {
            fxSceneLight l = FX_DESC_INIT(fxSceneLight);
            float point[3] = {0.0f, 1.0f, 0.0f};
            int code;
            l.toSun[1] = 1.0f;
            l.sunColor[0] = l.sunColor[1] = l.sunColor[2] = 1.0f;
            l.toSun[c] = f;
            code = api->setSceneLight(p, &l);
            CHECKV(finite ? (code == FX_ERROR_NONE || code == FX_ERROR_INVALID_VALUE) : code == FX_ERROR_INVALID_VALUE, f);
            l.toSun[c] = c == 1 ? 1.0f : 0.0f;
            l.sunColor[c] = f;
            code = api->setSceneLight(p, &l);
            CHECKV(code == (finite && f >= 0.0f ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), f);
            l.sunColor[c] = 1.0f;
            l.ambient[c] = f;
            code = api->setSceneLight(p, &l);
            CHECKV(code == (finite && f >= 0.0f ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), f);
            point[c] = f;
            CHECKV(api->fireReaction(explosion, "explosion", point) ==
                       (finite && fabsf(f) <= FX_MAX_WORLD_COORDINATE ? FX_ERROR_NONE : FX_ERROR_INVALID_VALUE), f);
        }
    }
    api->clearSceneLight(p);
    for (i = 0; i < 30; ++i) CHECK(api->continueReaction(explosion, 0, 1.0f / 30.0f, NULL) == FX_ERROR_NONE);
    {
        fxParticleCheck check;
        api->checkParticles(explosion, &check);
        CHECK(check.nonFinite == 0);
    }
}

/* Each float of fxViewDesc, each int, through renderView and declarePasses. `q` has no reactions:
 * an accepted view draws nothing and costs little. */
static void sweepViews(Run* run, const fxApi* api, fxPlugin* q) {
    int i, field, code, targets = 0;
    fxFrameBuilder frame = recordingFrame(&targets);
    for (i = 0; i < SPECIAL_FLOATS; ++i) {
        const float f = specialFloat(i);
        const int finite = isfinite(f);
        for (field = 0; field < 16 + 16 + 3 + 4; ++field) {
            fxViewDesc v = goodView();
            float* slot = field < 16 ? &v.view[field]
                          : field < 32 ? &v.proj[field - 16]
                          : field < 35 ? &v.eye[field - 32]
                          : field == 35 ? &v.nearPlane
                          : field == 36 ? &v.farPlane
                          : field == 37 ? &v.depthRangeNear : &v.depthRangeFar;
            *slot = f;
            code = api->renderView(q, &v);
            CHECK_GL(f);
            if (!finite) {
                CHECKV(code == FX_ERROR_INVALID_VIEW, field * 1000 + i);
            } else {
                CHECKV(code == FX_ERROR_NONE || code == FX_ERROR_INVALID_VIEW || code == FX_ERROR_INVALID_VALUE,
                       field * 1000 + i);
            }
            if (field == 35) CHECKV((code == FX_ERROR_NONE) == (f > 0.0f && f < v.farPlane), f);
            code = api->declarePasses(q, &v, &frame);
            CHECK_GL(f);
            if (field < 37) CHECKV(finite ? (code == FX_ERROR_NONE || code == FX_ERROR_INVALID_VIEW) : code == FX_ERROR_INVALID_VIEW,
                                   field * 1000 + i);
        }
    }
    for (i = 0; i < INT_COUNT; ++i) {
        const int n = kInts[i];
        fxViewDesc v = goodView();
        v.width = n;
        code = api->renderView(q, &v);
        CHECK_GL(n);
        CHECKV((code == FX_ERROR_NONE) == (n >= 1 && n <= FX_MAX_VIEW_SIZE), n);
        v = goodView();
        v.height = n;
        CHECKV((api->declarePasses(q, &v, &frame) == FX_ERROR_NONE) == (n >= 1 && n <= FX_MAX_VIEW_SIZE), n);
        CHECK_GL(n);
        v = goodView();
        v.depthOrder = n;
        CHECKV((api->renderView(q, &v) == FX_ERROR_NONE) == (n == 0 || n == 1), n);
        v = goodView();
        v.handedness = n;
        CHECKV((api->renderView(q, &v) == FX_ERROR_NONE) == (n == 0 || n == 1), n);
        v = goodView();
        v.depthSource = n;
        code = api->renderView(q, &v);
        CHECKV(n == FX_DEPTH_FROM_FRAMEBUFFER || n == FX_DEPTH_FROM_NOTHING ? code == FX_ERROR_NONE : code != FX_ERROR_NONE, n);
        CHECK_GL(n);
        v = goodView();
        v.depthSource = FX_DEPTH_FROM_TEXTURE;
        v.depthTexture = (uint32_t)n;
        code = api->renderView(q, &v); /* small names may be the plugins' own textures */
        CHECKV(code == FX_ERROR_NONE || code == FX_ERROR_NULL_ARGUMENT || code == FX_ERROR_UNSUPPORTED_DEPTH ||
                   code == FX_ERROR_SIZE_MISMATCH, n);
        CHECKV(n != 0 ? 1 : code == FX_ERROR_NULL_ARGUMENT, n);
        CHECK_GL(n);
        v.size = (uint32_t)n;
        CHECKV((api->renderView(q, &v) == FX_ERROR_BAD_DESCRIPTOR) == (v.size != sizeof v), n);
        CHECK_GL(n);
    }
}

/* ---- 3. dead handles -------------------------------------------------------------------------- */

static void deadHandles(Run* run, const fxApi* api) {
    int error = -1;
    fxPlugin* dead = makePlugin(api, &error);
    fxViewDesc v = goodView();
    fxStats stats;
    char buffer[16];
    float point[3] = {0.0f, 0.0f, 0.0f};
    struct {
        char bytes[64];
    } foreignStorage;
    fxPlugin* foreign = (fxPlugin*)(void*)&foreignStorage;
    CHECK(dead != NULL);
    if (!dead) return;
    api->destroy(dead);
    /* Each reads through the handle if nothing checks it: ASan's heap-use-after-free. */
    CHECK(api->reactionCount(dead) == 0);
    CHECK(api->renderView(dead, &v) == FX_ERROR_INVALID_HANDLE);
    CHECK_GL(0);
    CHECK(api->continueReaction(dead, 0, 0.01f, NULL) == FX_ERROR_INVALID_HANDLE);
    CHECK(api->fireReaction(dead, "x", point) == FX_ERROR_INVALID_HANDLE);
    CHECK(api->reactionName(dead, 0, buffer, sizeof buffer) == 0 && buffer[0] == '\0');
    CHECK(!api->prepareGl(dead, NULL) && !api->loadReactions(dead, "x.yaml", NULL));
    memset(&stats, 0x5A, sizeof stats);
    api->stats(dead, &stats);
    CHECK(stats.apiErrors == 0x5A5A5A5A); /* untouched */
    api->destroy(dead);                   /* twice: refused, nothing freed */
    CHECK(api->reactionCount(foreign) == 0);
    CHECK(api->setParticleShape(foreign, 0) == FX_ERROR_INVALID_HANDLE);
    api->destroy(foreign);
    CHECK(api->continueReaction(NULL, 0, 0.01f, NULL) == FX_ERROR_NULL_ARGUMENT);
    api->destroy(NULL);
}

/* ---- 4. nothing silent, nothing left behind ---------------------------------------------------- */

static void depthSources(Run* run, const fxApi* api, fxPlugin* p) {
    GLuint rgba8 = 0, depth24 = 0, r32f = 0, volume = 0, deleted = 0, unbound = 0;
    fxViewDesc v = goodView();
    int before = apiErrors(api, p), code;
    gl.GenTextures(1, &rgba8);
    gl.BindTexture(GL_TEXTURE_2D, rgba8);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, WIDTH, HEIGHT, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    gl.GenTextures(1, &depth24);
    gl.BindTexture(GL_TEXTURE_2D, depth24);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, WIDTH, HEIGHT, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    gl.GenTextures(1, &r32f);
    gl.BindTexture(GL_TEXTURE_2D, r32f);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R32F, WIDTH, HEIGHT, 0, GL_RED, GL_FLOAT, NULL);
    gl.GenTextures(1, &volume);
    gl.BindTexture(GL_TEXTURE_3D, volume);
    gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    gl.GenTextures(1, &deleted);
    gl.BindTexture(GL_TEXTURE_2D, deleted);
    gl.DeleteTextures(1, &deleted);
    gl.GenTextures(1, &unbound);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindTexture(GL_TEXTURE_3D, 0);
    CHECK_GL(0);

    v.depthSource = FX_DEPTH_FROM_LINEAR;
    v.depthTexture = rgba8;
    CHECK(api->renderView(p, &v) == FX_ERROR_UNSUPPORTED_DEPTH);
    CHECK_GL(rgba8);
    v.depthTexture = depth24;
    CHECK(api->renderView(p, &v) == FX_ERROR_UNSUPPORTED_DEPTH);
    CHECK_GL(depth24);
    v.depthTexture = r32f;
    CHECK(api->renderView(p, &v) == FX_ERROR_NONE);
    CHECK_GL(r32f);
    v.depthSource = FX_DEPTH_FROM_TEXTURE;
    CHECK(api->renderView(p, &v) == FX_ERROR_UNSUPPORTED_DEPTH); /* R32F is not a depth format */
    CHECK_GL(r32f);
    v.depthTexture = depth24;
    CHECK(api->renderView(p, &v) == FX_ERROR_NONE);
    CHECK_GL(depth24);
    {
        const GLuint names[4] = {volume, deleted, unbound, 999999u};
        int i, s;
        for (s = 0; s < 2; ++s) {
            v.depthSource = s == 0 ? FX_DEPTH_FROM_TEXTURE : FX_DEPTH_FROM_LINEAR;
            for (i = 0; i < 4; ++i) {
                v.depthTexture = names[i];
                code = api->renderView(p, &v);
                CHECKV(code == FX_ERROR_UNSUPPORTED_DEPTH, names[i]);
                CHECK_GL(names[i]); /* the 3D name's bind error is not left in the host's context */
            }
        }
    }
    /* declareShadowPasses with no out-pointer: refused, not OK. */
    {
        int targets = 0;
        fxFrameBuilder frame = recordingFrame(&targets);
        v = goodView();
        CHECK(api->declareShadowPasses(p, &v, &frame, NULL) == FX_ERROR_NULL_ARGUMENT);
        CHECK_GL(0);
    }
    /* 2 + 1 + 8 + 1 refusals above, each counted. */
    CHECKV(apiErrors(api, p) - before == 12, apiErrors(api, p) - before);
    gl.DeleteTextures(1, &rgba8);
    gl.DeleteTextures(1, &depth24);
    gl.DeleteTextures(1, &r32f);
    gl.DeleteTextures(1, &volume);
    gl.DeleteTextures(1, &unbound);
    CHECK_GL(0);
}

/* prepareGl and renderView with no context current: NoGlContext in the standard form, counted;
 * then, with the context current again, both recover and the smoke is drawn. */
static void noContext(Run* run, const fxApi* api, fxPlugin* p, OSMesaContext context, unsigned char* buffer) {
    const int before = apiErrors(api, p), logged = g_host.errors;
    fxViewDesc v = goodView();
    int code, pixels;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    CHECK(!api->prepareGl(p, NULL));
    CHECK(strstr(g_host.lastError, "fx: error[NoGlContext] prepareGl: ") == g_host.lastError);
    CHECK(api->renderView(p, &v) == FX_ERROR_NO_GL_CONTEXT);
    CHECK(strstr(g_host.lastError, "fx: error[NoGlContext] renderView: ") == g_host.lastError);
    CHECK(g_host.errors == logged + 2 && apiErrors(api, p) == before + 2);
    CHECK(OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT));
    CHECK_GL(0);
    CHECK(api->prepareGl(p, NULL));
    pixels = drawSmoke(run, api, p, &code);
    CHECK(code == FX_ERROR_NONE);
    CHECKV(pixels > 300, pixels);
}

/* ---- 5. a checked loader -------------------------------------------------------------------- */

/* Every name the loader asks for returns NULL in turn (with no other plugin alive, so each new
 * plugin loads the table again): the load is refused naming it (a function the drawing calls) or
 * goes ahead; no crash, no GL error. Then one host returns NULL for every name that went ahead
 * at once, and the smoke must still be drawn: the list of needed functions is complete for
 * these paths, and the optional ones (debug groups, clip control) degrade. */
static void loaderSweep(Run* run, const fxApi* api, const char* reactionFile) {
    int i, error, code, refused = 0, accepted = 0, pixels, step;
    fxPlugin* p;
    char line[1400];
    g_host.recording = 1;
    p = makePlugin(api, &error);
    CHECK(p != NULL);
    if (!p) return;
    CHECK(api->prepareGl(p, NULL));
    api->destroy(p);
    g_host.recording = 0;
    CHECKV(g_host.nameCount > 100, g_host.nameCount);
    for (i = 0; i < g_host.nameCount; ++i) {
        fxViewDesc v = goodView();
        g_host.nullName = g_host.names[i];
        g_host.lastError[0] = '\0';
        p = makePlugin(api, &error);
        code = api->renderView(p, &v);
        CHECK_GL(i);
        g_host.nullSet[i] = code == FX_ERROR_NONE;
        if (code == FX_ERROR_NONE) {
            ++accepted;
        } else {
            ++refused;
            CHECKV(code == FX_ERROR_NO_GL_CONTEXT, i);
            /* The refusal names the function. */
            CHECKV(strstr(g_host.lastError, g_host.names[i]) != NULL, i);
            if (strstr(g_host.lastError, g_host.names[i]) == NULL) note(run, g_host.lastError);
        }
        api->destroy(p);
    }
    g_host.nullName = NULL;
    snprintf(line, sizeof line, "loader: %d names asked for; NULL for each in turn: %d refused (named), %d accepted",
             g_host.nameCount, refused, accepted);
    note(run, line);
    CHECK(refused > 50 && accepted > 50);

    g_host.nullSetOn = 1;
    g_host.warnings = 0;
    p = makePlugin(api, &error);
    CHECK(api->loadReactions(p, reactionFile, NULL));
    for (step = 0; step < 60; ++step) api->continueReaction(p, 0, 1.0f / 60.0f, NULL);
    CHECK(api->prepareGl(p, NULL));
    pixels = drawSmoke(run, api, p, &code);
    CHECK(code == FX_ERROR_NONE);
    CHECKV(pixels > 300, pixels);
    CHECK(g_host.warnings >= 1 && strstr(g_host.lastWarning, "switched off") != NULL);
    snprintf(line, sizeof line, "loader: all %d accepted names NULL at once: smoke drawn (%d pixels); %s", accepted,
             pixels, g_host.lastWarning);
    note(run, line);
    api->destroy(p);
    g_host.nullSetOn = 0;
    for (i = 0; i < g_host.nameCount; ++i) free(g_host.names[i]);
    g_host.nameCount = 0;
}

int fxHostileHostCheck(const char* reactionFile, const char* explosionFile, char* report, int capacity) {
    static unsigned char buffer[WIDTH * HEIGHT * 4];
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    Run r, *run = &r;
    const fxApi* api = fxGetApi(FX_API_VERSION);
    OSMesaContext context;
    fxPlugin *p, *q, *explosion;
    int error = -1, step, code, pixels;
    r.report = report;
    r.capacity = capacity;
    r.used = 0;
    r.failed = 0;
    report[0] = '\0';
    memset(&g_host, 0, sizeof g_host);
    CHECK(api != NULL);
    if (!api) return r.failed;
    context = OSMesaCreateContextAttribs(attribs, NULL);
    CHECK(context != NULL);
    if (!context) return r.failed;

    /* With no context current, before any plugin loaded GL: NoGlContext, then recovery. */
    p = makePlugin(api, &error);
    CHECK(p != NULL);
    if (!p) return r.failed;
    CHECK(!api->prepareGl(p, NULL));
    CHECK(strstr(g_host.lastError, "fx: error[NoGlContext] prepareGl: ") == g_host.lastError);
    CHECK(apiErrors(api, p) == 1);
    CHECK(OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT) && loadGl());
    CHECK_GL(0);

    garbageDescriptors(run, api);
    CHECK(api->loadReactions(p, reactionFile, NULL));
    for (step = 0; step < 90; ++step) CHECK(api->continueReaction(p, 0, 1.0f / 60.0f, NULL) == FX_ERROR_NONE);
    CHECK(api->prepareGl(p, NULL));
    pixels = drawSmoke(run, api, p, &code);
    CHECK(code == FX_ERROR_NONE);
    CHECKV(pixels > 300, pixels);

    q = makePlugin(api, &error);
    explosion = makePlugin(api, &error);
    CHECK(q != NULL && explosion != NULL);
    if (!q || !explosion) return r.failed;
    CHECK(api->loadReactions(explosion, explosionFile, NULL));
    sweepSimulation(run, api, p);
    sweepLightAndFire(run, api, p, explosion);
    sweepViews(run, api, q);
    deadHandles(run, api);
    depthSources(run, api, p);
    noContext(run, api, p, context, buffer);
    api->destroy(explosion);
    api->destroy(q);
    api->destroy(p);
    CHECK_GL(0);

    loaderSweep(run, api, reactionFile);
    CHECK_GL(0);
    OSMesaDestroyContext(context);
    return r.failed;
}
