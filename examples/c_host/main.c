/* c_host: the CubeFx plugin driven from C99 through its C table only (fx/fx.h).
 *
 * An OSMesa context (compatibility profile, so the host can draw with glBegin/glEnd) renders a
 * grey ground plane and a blue post in front of one spinning rear wheel into OSMesa's own colour
 * and depth buffer, simulates 1.5 s of smoke, then lets the plugin draw it with one call,
 * fxApi.renderView, taking the scene depth from that buffer. It reads the pixels back, writes a
 * PNG (stb_image_write) and checks what a host relies on; the exit status is 0 only when:
 *   - the smoke is there: more than MIN_SMOKE_PIXELS pixels changed against the frame without it;
 *   - the smoke is hidden behind the post: no pixel of the post changed;
 *   - the plugin logged no error and raised no GL error.
 *
 *   c_host <reactions.yaml> <out.png>
 */
#include <GL/osmesa.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fx/fx.h>
#include <stb/stb_image_write.h>

#define WIDTH 320
#define HEIGHT 240
#define MIN_SMOKE_PIXELS 3000 /* of 76800; the cloud covers about a fifth of the frame */

/* The few GL entry points the host itself needs, from OSMesaGetProcAddress. */
static struct {
    void (*ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf);
    void (*Clear)(GLbitfield);
    void (*Enable)(GLenum);
    void (*DepthFunc)(GLenum);
    void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
    void (*MatrixMode)(GLenum);
    void (*LoadMatrixf)(const GLfloat*);
    void (*Begin)(GLenum);
    void (*End)(void);
    void (*Color3f)(GLfloat, GLfloat, GLfloat);
    void (*Vertex3f)(GLfloat, GLfloat, GLfloat);
    void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    GLenum (*GetError)(void);
} gl;

static int loadGl(void) {
    /* Each member takes the address OSMesa gives for its name; function pointers share one
     * representation here, so the bytes are copied rather than the pointer type punned. */
    OSMESAproc proc;
#define LOAD(f) (proc = OSMesaGetProcAddress("gl" #f), memcpy(&gl.f, &proc, sizeof proc), proc != NULL)
    return LOAD(ClearColor) && LOAD(Clear) && LOAD(Enable) && LOAD(DepthFunc) && LOAD(Viewport) &&
           LOAD(MatrixMode) && LOAD(LoadMatrixf) && LOAD(Begin) && LOAD(End) && LOAD(Color3f) &&
           LOAD(Vertex3f) && LOAD(ReadPixels) && LOAD(GetError);
#undef LOAD
}

/* ---- the host's callbacks --------------------------------------------------------------- */

static int g_errors = 0;

static void* hostProc(void* user, const char* name) {
    OSMESAproc f = OSMesaGetProcAddress(name);
    void* p;
    (void)user;
    memcpy(&p, &f, sizeof p); /* POSIX: a function pointer fits a void* */
    return p;
}

static void hostLog(void* user, int level, const char* message) {
    (void)user;
    fprintf(stderr, "[fx %s] %s\n", level == FX_LOG_ERROR ? "error" : level == FX_LOG_WARNING ? "warning" : "info",
            message);
    if (level == FX_LOG_ERROR) ++g_errors;
}

static void hostReport(void* user, const fxDiagnostic* d) {
    (void)user;
    fprintf(stderr, "%s:%d:%d: %s: %s (%s)\n", d->file, d->line, d->column, d->key, d->message,
            fxErrorCodeName(d->code));
    ++g_errors;
}

static int hostWheelCount(void* user) {
    (void)user;
    return 1;
}

/* One rear wheel at the origin in a standing burnout. */
static void hostWheel(void* user, int index, fxWheelContact* out) {
    (void)user;
    (void)index;
    memset(out, 0, sizeof *out);
    out->slip = 1.0f;
    out->surface = FX_SURFACE_ASPHALT;
    out->grounded = 1;
    out->rear = 1;
}

/* ---- camera: right-handed, OpenGL's conventions ----------------------------------------- */

static void lookAt(const float eye[3], const float at[3], float m[16]) {
    float f[3], s[3], u[3], n;
    int i;
    for (i = 0; i < 3; ++i) f[i] = at[i] - eye[i];
    n = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= n;
    s[0] = -f[2]; s[1] = 0.0f; s[2] = f[0]; /* f x (0,1,0) */
    n = sqrtf(s[0] * s[0] + s[2] * s[2]);
    s[0] /= n; s[2] /= n;
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

static void perspective(float fovY, float aspect, float zNear, float zFar, float m[16]) {
    const float t = 1.0f / tanf(0.5f * fovY);
    memset(m, 0, 16 * sizeof *m);
    m[0] = t / aspect;
    m[5] = t;
    m[10] = (zFar + zNear) / (zNear - zFar);
    m[11] = -1.0f;
    m[14] = 2.0f * zFar * zNear / (zNear - zFar);
}

/* ---- the scene --------------------------------------------------------------------------- */

static const float kPost[3] = {0.2f, 0.35f, 0.85f}; /* the post's colour: found again by value */

static void drawScene(const float view[16], const float proj[16]) {
    gl.Viewport(0, 0, WIDTH, HEIGHT);
    gl.ClearColor(0.45f, 0.55f, 0.7f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.MatrixMode(GL_PROJECTION);
    gl.LoadMatrixf(proj);
    gl.MatrixMode(GL_MODELVIEW);
    gl.LoadMatrixf(view);
    gl.Begin(GL_QUADS);
    gl.Color3f(0.32f, 0.33f, 0.36f); /* ground, y = 0 */
    gl.Vertex3f(-40.0f, 0.0f, 40.0f);
    gl.Vertex3f(40.0f, 0.0f, 40.0f);
    gl.Vertex3f(40.0f, 0.0f, -40.0f);
    gl.Vertex3f(-40.0f, 0.0f, -40.0f);
    gl.Color3f(kPost[0], kPost[1], kPost[2]); /* a post between the camera and the smoke */
    gl.Vertex3f(0.3f, 0.0f, 1.6f);
    gl.Vertex3f(0.8f, 0.0f, 1.6f);
    gl.Vertex3f(0.8f, 3.0f, 1.6f);
    gl.Vertex3f(0.3f, 3.0f, 1.6f);
    gl.End();
}

static unsigned char* readFrame(void) {
    unsigned char* rows = malloc(WIDTH * HEIGHT * 4);
    unsigned char* image = malloc(WIDTH * HEIGHT * 4);
    int y;
    if (!rows || !image) exit(3);
    gl.ReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, rows);
    for (y = 0; y < HEIGHT; ++y) /* GL's rows go bottom-up, the PNG's top-down */
        memcpy(image + (size_t)y * WIDTH * 4, rows + (size_t)(HEIGHT - 1 - y) * WIDTH * 4, WIDTH * 4);
    free(rows);
    return image;
}

static int isPost(const unsigned char* p) {
    int c;
    for (c = 0; c < 3; ++c)
        if (abs(p[c] - (int)(kPost[c] * 255.0f + 0.5f)) > 1) return 0;
    return 1;
}

int main(int argc, char** argv) {
    static unsigned char buffer[WIDTH * HEIGHT * 4]; /* OSMesa's colour buffer */
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    const float eye[3] = {2.6f, 1.0f, 3.6f}, at[3] = {0.0f, 0.6f, -0.5f};
    const fxApi* fx;
    /* In C99 FX_DESC_INIT(T) is {.size = sizeof(T)}: the size set, every other field zero. */
    fxHostCallbacks host = FX_DESC_INIT(fxHostCallbacks);
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    fxViewDesc view = FX_DESC_INIT(fxViewDesc);
    fxDiagnosticSink sink;
    fxStats stats;
    fxPlugin* plugin;
    OSMesaContext context;
    unsigned char *before, *after;
    int error = FX_ERROR_NONE, step, r, i, smoke = 0, postPixels = 0, postChanged = 0, glErrors = 0, failed = 0;

    if (argc != 3) {
        fprintf(stderr, "usage: c_host <reactions.yaml> <out.png>\n");
        return 2;
    }
    context = OSMesaCreateContextAttribs(attribs, NULL);
    if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT) || !loadGl()) {
        fprintf(stderr, "c_host: no OSMesa GL 3.3 compatibility context\n");
        return 3;
    }

    /* 1. The table for the API these headers describe; null if the library cannot serve it. */
    fx = fxGetApi(FX_API_VERSION);
    if (!fx) {
        fprintf(stderr, "c_host: the library (API %u.%u) cannot serve API %u.%u\n", fxApiVersion() >> 16,
                fxApiVersion() & 0xffffu, FX_API_VERSION_MAJOR, FX_API_VERSION_MINOR);
        return 1;
    }
    host.getProcAddress = hostProc;
    host.log = hostLog;
    host.wheelCount = hostWheelCount;
    host.wheel = hostWheel;
    desc.host = &host;
    sink.user = NULL;
    sink.report = hostReport;
    plugin = fx->create(&desc, &error);
    if (!plugin || !fx->loadReactions(plugin, argv[1], &sink) ||
        !fx->prepareGl(plugin, &sink)) {
        fprintf(stderr, "c_host: the plugin did not start (%s)\n", fxErrorCodeName(error));
        return 1;
    }

    /* 2. 1.5 s of smoke at 60 Hz. */
    for (step = 0; step < 90; ++step)
        for (r = 0; r < fx->reactionCount(plugin); ++r) fx->continueReaction(plugin, r, 1.0f / 60.0f, NULL);

    /* 3. The scene, then the smoke over it with the scene's own z-buffer. */
    view.name = "main";
    lookAt(eye, at, view.view);
    view.nearPlane = 0.1f;
    view.farPlane = 500.0f;
    perspective(55.0f * 3.14159265f / 180.0f, (float)WIDTH / HEIGHT, view.nearPlane, view.farPlane, view.proj);
    memcpy(view.eye, eye, sizeof view.eye);
    view.width = WIDTH;
    view.height = HEIGHT;
    /* Defaults: right-handed, standard depth, depth from the bound framebuffer (OSMesa's). */
    drawScene(view.view, view.proj);
    before = readFrame();
    error = fx->renderView(plugin, &view);
    after = readFrame();
    while (gl.GetError() != GL_NO_ERROR && glErrors < 100) ++glErrors;

    /* 4. Checks. */
    for (i = 0; i < WIDTH * HEIGHT * 4; i += 4) {
        const int changed = memcmp(before + i, after + i, 3) != 0;
        smoke += changed;
        if (isPost(before + i)) {
            ++postPixels;
            postChanged += changed;
        }
    }
    fx->stats(plugin, &stats);
    printf("renderView: %s; particles alive %d, drawn %d\n", fxErrorCodeName(error), stats.particlesAlive,
           stats.particlesDrawn);
    printf("smoke pixels %d of %d (need > %d); post pixels %d, changed %d (need 0)\n", smoke, WIDTH * HEIGHT,
           MIN_SMOKE_PIXELS, postPixels, postChanged);
    if (!stbi_write_png(argv[2], WIDTH, HEIGHT, 4, after, WIDTH * 4)) {
        fprintf(stderr, "c_host: could not write %s\n", argv[2]);
        failed = 1;
    }
    if (error != FX_ERROR_NONE || smoke <= MIN_SMOKE_PIXELS || postPixels < 500 || postChanged != 0 ||
        g_errors != 0 || glErrors != 0 || stats.apiErrors != 0) {
        printf("c_host: FAIL (plugin errors %d, GL errors %d, API errors %d)\n", g_errors, glErrors, stats.apiErrors);
        failed = 1;
    }

    /* 5. Destroy the plugin with the context current (it deletes its GL objects), then it. */
    fx->destroy(plugin);
    OSMesaDestroyContext(context);
    free(before);
    free(after);
    if (!failed) printf("c_host: ok\n");
    return failed;
}
