/* c89_host: a host written in C89 (ANSI C) that drives the plugin through fx/fx.h alone, as a
 * 1990s-era engine would: no // comments, declarations at the start of blocks, no designated
 * initialisers (FX_DESC_INIT expands to the positional {sizeof(T)} here), no <stdint.h> beyond
 * what fx.h includes, no C99 maths (sqrt and tan, not sqrtf and tanf). Built with
 * -std=c89 -pedantic-errors by CMake (the build's C compiler) and by era_test.sh (gcc and clang).
 *
 * On a window-less OSMesa context it creates the plugin, loads one reaction file, builds the GL
 * programs, has an edited text with bad data refused (a diagnostic at its line), simulates 1.5 s of a rear-wheel burnout, then draws the smoke with fxApi.renderView
 * over a cleared frame (depth from OSMesa's own z-buffer). The exit status is the number of
 * failed checks; each failed check prints its line.
 *
 *   c89_host <reactions.yaml>
 */
#include <GL/osmesa.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <fx/fx.h>

#include "EraHost.h" /* CHECK, g_failed, the burnout car */

#define WIDTH 160
#define HEIGHT 120
#define MIN_SMOKE_PIXELS 500 /* of 19200; the burnout cloud covers several thousand */

/* ---- GL: the three entry points the host itself calls ----------------------------------- */

static struct {
    void (*ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf);
    void (*Clear)(GLbitfield);
    void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    GLenum (*GetError)(void);
} gl;

static int loadGl(void) {
    OSMESAproc proc;
#define LOAD(f) (proc = OSMesaGetProcAddress("gl" #f), memcpy(&gl.f, &proc, sizeof proc), proc != NULL)
    return LOAD(ClearColor) && LOAD(Clear) && LOAD(ReadPixels) && LOAD(GetError);
#undef LOAD
}

/* ---- the host's callbacks --------------------------------------------------------------- */

typedef struct Host {
    int errorsLogged;
    int diagnostics;
    int firstDiagnosticLine;
} Host;

static void* hostProc(void* user, const char* name) {
    OSMESAproc f = OSMesaGetProcAddress(name);
    void* p;
    (void)user;
    memcpy(&p, &f, sizeof p); /* POSIX: a function pointer fits a void* */
    return p;
}

static void hostLog(void* user, int level, const char* message) {
    Host* h = (Host*)user;
    if (level == FX_LOG_ERROR) {
        ++h->errorsLogged;
        fprintf(stderr, "[fx error] %s\n", message);
    }
}

static void hostReport(void* user, const fxDiagnostic* d) {
    Host* h = (Host*)user;
    if (h->diagnostics++ == 0) h->firstDiagnosticLine = d->line;
    fprintf(stderr, "%s:%d:%d: %s: %s (%s)\n", d->file, d->line, d->column, d->key, d->message,
            fxErrorCodeName(d->code));
}

/* ---- camera: right-handed, OpenGL's conventions, column-major ---------------------------- */

static void lookAt(const float eye[3], const float at[3], float m[16]) {
    float f[3], s[3], u[3];
    double n;
    int i;
    for (i = 0; i < 3; ++i) f[i] = at[i] - eye[i];
    n = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] = (float)(f[i] / n);
    s[0] = -f[2]; s[1] = 0.0f; s[2] = f[0]; /* f x (0,1,0) */
    n = sqrt(s[0] * s[0] + s[2] * s[2]);
    s[0] = (float)(s[0] / n); s[2] = (float)(s[2] / n);
    u[0] = s[1] * f[2] - s[2] * f[1]; u[1] = s[2] * f[0] - s[0] * f[2]; u[2] = s[0] * f[1] - s[1] * f[0];
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

static void perspective(double fovY, double aspect, float zNear, float zFar, float m[16]) {
    const double t = 1.0 / tan(0.5 * fovY);
    memset(m, 0, 16 * sizeof *m);
    m[0] = (float)(t / aspect);
    m[5] = (float)t;
    m[10] = (zFar + zNear) / (zNear - zFar);
    m[11] = -1.0f;
    m[14] = 2.0f * zFar * zNear / (zNear - zFar);
}

int main(int argc, char** argv) {
    static unsigned char buffer[WIDTH * HEIGHT * 4]; /* OSMesa's colour buffer */
    static unsigned char before[WIDTH * HEIGHT * 4];
    static const char kBadReaction[] = "reactions:\n  - name: broken\n    type: wheel_smoke\n    emission: {rate: -5}\n";
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    const float eye[3] = {5.0f, 2.5f, 7.0f}, at[3] = {0.0f, 0.8f, 1.3f};
    /* FX_DESC_INIT in C89: {sizeof(T)}, size first, every other field zero. */
    fxHostCallbacks callbacks = FX_DESC_INIT(fxHostCallbacks);
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    fxViewDesc view = FX_DESC_INIT(fxViewDesc);
    fxRenderOptions options = FX_DESC_INIT(fxRenderOptions);
    const fxApi* fx;
    fxDiagnosticSink sink;
    fxStats stats;
    fxPlugin* plugin;
    Host host;
    OSMesaContext context;
    int error = -1, step, r, i, reactions, smoke = 0, glErrors = 0, rendered;

    if (argc != 2) {
        fprintf(stderr, "usage: c89_host <reactions.yaml>\n");
        return 100;
    }
    memset(&host, 0, sizeof host);

    /* The positional initialiser set the size and zero-filled the rest. */
    CHECK(callbacks.size == sizeof(fxHostCallbacks) && callbacks.user == NULL && callbacks.wheel == NULL);
    CHECK(desc.size == sizeof(fxPluginDesc) && desc.apiVersion == 0 && desc.host == NULL && desc.seed == 0);
    CHECK(view.size == sizeof(fxViewDesc) && view.name == NULL && view.proj[15] == 0.0f && view.width == 0 &&
          view.depthSource == FX_DEPTH_FROM_FRAMEBUFFER && view.depthRangeFar == 0.0f);
    CHECK(options.size == sizeof(fxRenderOptions) && options.techniqueOverride == 0 && options.bilinearUpsample == 0);

    context = OSMesaCreateContextAttribs(attribs, NULL);
    if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT) || !loadGl()) {
        fprintf(stderr, "c89_host: no OSMesa GL 3.3 compatibility context\n");
        return 100;
    }

    fx = fxGetApi(FX_API_VERSION);
    CHECK(fx != NULL);
    if (!fx) return g_failed;
    CHECK(fx->size == sizeof(fxApi) && fx->version == FX_API_VERSION);

    callbacks.user = &host;
    callbacks.getProcAddress = hostProc;
    callbacks.log = hostLog;
    callbacks.wheelCount = hostWheelCount;
    callbacks.wheel = hostWheel;
    desc.host = &callbacks;
    desc.seed = 1;
    sink.user = &host;
    sink.report = hostReport;

    plugin = fx->create(&desc, &error);
    CHECK(plugin != NULL && error == FX_ERROR_NONE);
    if (!plugin) return g_failed;

    CHECK(fx->loadReactions(plugin, argv[1], &sink));
    CHECK(host.diagnostics == 0);
    reactions = fx->reactionCount(plugin);
    CHECK(reactions > 0);

    /* An edited text of that file with bad data is refused with a diagnostic that names its line
     * (and logged as an error); the running set is kept. */
    CHECK(!fx->loadReactionsFromText(plugin, argv[1], kBadReaction, sizeof kBadReaction - 1, &sink));
    CHECK(host.diagnostics > 0 && host.firstDiagnosticLine == 4);
    CHECK(host.errorsLogged > 0);
    CHECK(fx->reactionCount(plugin) == reactions);
    host.diagnostics = 0;
    host.errorsLogged = 0;
    CHECK(fx->setRenderOptions(plugin, &options) == FX_ERROR_NONE);
    CHECK(fx->prepareGl(plugin, &sink));

    /* 1.5 s at 60 Hz. */
    for (step = 0; step < 90; ++step)
        for (r = 0; r < fx->reactionCount(plugin); ++r)
            CHECK(fx->continueReaction(plugin, r, 1.0f / 60.0f, NULL) == FX_ERROR_NONE);
    fx->stats(plugin, &stats);
    CHECK(stats.particlesAlive > 0);

    view.name = "c89";
    lookAt(eye, at, view.view);
    view.nearPlane = 0.1f;
    view.farPlane = 500.0f;
    perspective(55.0 * 3.14159265358979 / 180.0, (double)WIDTH / HEIGHT, view.nearPlane, view.farPlane, view.proj);
    memcpy(view.eye, eye, sizeof view.eye);
    view.width = WIDTH;
    view.height = HEIGHT;
    gl.ClearColor(0.2f, 0.3f, 0.45f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.ReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, before);
    rendered = fx->renderView(plugin, &view);
    CHECK(rendered == FX_ERROR_NONE);
    gl.ReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, buffer);
    while (gl.GetError() != GL_NO_ERROR && glErrors < 100) ++glErrors;
    for (i = 0; i < WIDTH * HEIGHT * 4; i += 4) smoke += memcmp(before + i, buffer + i, 3) != 0;

    fx->stats(plugin, &stats);
    printf("c89_host: %d reaction(s), %d particles alive, %d drawn, %d of %d pixels changed (need > %d),"
           " GL errors %d, API errors %d, errors logged %d\n",
           stats.reactions, stats.particlesAlive, stats.particlesDrawn, smoke, WIDTH * HEIGHT, MIN_SMOKE_PIXELS,
           glErrors, stats.apiErrors, host.errorsLogged);
    CHECK(stats.particlesDrawn > 0);
    CHECK(smoke > MIN_SMOKE_PIXELS);
    CHECK(glErrors == 0);
    CHECK(stats.apiErrors == 0);
    CHECK(host.errorsLogged == 0);

    fx->destroy(plugin); /* with the context current: it deletes its GL objects */
    OSMesaDestroyContext(context);
    printf("c89_host: %s\n", g_failed ? "FAIL" : "ok");
    return g_failed;
}
