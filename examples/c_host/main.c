/* c_host: the CubeFx plugin driven from C99 through its C table only (fx/fx.h), by a Z-up host
 * with linear fog and a two-player split screen.
 *
 * The host's world is Z-up (X east, Y north, Z up): a grey ground plane at z = 0, a blue post, and
 * a car creeping north with one spinning rear wheel. An OSMesa context (compatibility profile, so
 * the host draws with glBegin/glEnd and fogs with glFog) holds one 640 x 240 framebuffer, two
 * players' views side by side. Each view sets its own glViewport and a scissor on its half, clears
 * it, draws the fogged scene and then lets the plugin draw that view's smoke with one call,
 * fxApi.renderView: the plugin is told the world is Z-up (fxPluginDesc.upAxis) and gets the same
 * fog, the view's own camera, and the scene depth of the bound framebuffer. After 1.5 s of smoke
 * the frame is drawn twice, without and with the plugin's calls; the smoke frame is written as a
 * PNG and the exit status is 0 only when:
 *   - each half shows smoke: more than MIN_SMOKE_PIXELS pixels of each half changed;
 *   - the smoke is hidden behind the post in player 1's view: no pixel of the post there changed;
 *   - the plugin logged no error and raised no GL error, and every renderView returned NONE.
 *
 * The lines between the fx-adapter begin/end markers are everything the host adds for the plugin
 * (examples/count_adapter_lines.sh counts them).
 *
 *   c_host <reactions.yaml> <out.png>
 */
#include <GL/osmesa.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fx/fx.h>
#include <stb/stb_image_write.h>

#define VIEW_WIDTH 320 /* one player's half */
#define HEIGHT 240
#define WIDTH (2 * VIEW_WIDTH)
#define PLAYERS 2
#define MIN_SMOKE_PIXELS 3000 /* per half, of 76800; the cloud covers about a fifth of a view */
#define STEP (1.0f / 60.0f)
#define NEAR_PLANE 0.1f
#define FAR_PLANE 500.0f

/* The few GL entry points the host itself needs, from OSMesaGetProcAddress. */
static struct {
    void (*ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf);
    void (*Clear)(GLbitfield);
    void (*Enable)(GLenum);
    void (*DepthFunc)(GLenum);
    void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
    void (*Scissor)(GLint, GLint, GLsizei, GLsizei);
    void (*Fogi)(GLenum, GLint);
    void (*Fogf)(GLenum, GLfloat);
    void (*Fogfv)(GLenum, const GLfloat*);
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
           LOAD(Scissor) && LOAD(Fogi) && LOAD(Fogf) && LOAD(Fogfv) && LOAD(MatrixMode) &&
           LOAD(LoadMatrixf) && LOAD(Begin) && LOAD(End) && LOAD(Color3f) && LOAD(Vertex3f) &&
           LOAD(ReadPixels) && LOAD(GetError);
#undef LOAD
}

/* ---- the host's world: Z-up, metres ------------------------------------------------------ */

typedef struct Car {
    float position[3], velocity[3]; /* its spinning rear wheel's contact patch and hub velocity */
} Car;

typedef struct Fog {
    float color[3]; /* also the sky: fogged geometry fades into it */
    float start, end; /* linear fog, as glFog's GL_LINEAR, over eye-space |z| */
} Fog;

/* One player's view: the left or the right half of the framebuffer. */
typedef struct Player {
    const char* name;
    int x; /* the half's left edge */
    float eye[3], at[3];
    float view[16], proj[16];
    int result; /* what renderView returned */
} Player;

static int g_errors = 0; /* errors the plugin logged */

/* ---- the host's callbacks --------------------------------------------------------------- */

// fx-adapter begin: callbacks (fxHostCallbacks: GL loader, log, the car's wheel)
static void* hostProc(void* user, const char* name) {
    (void)user;
    return (void*)(uintptr_t)OSMesaGetProcAddress(name); /* POSIX: a function pointer fits a void* */
}
static void hostLog(void* user, int level, const char* message) {
    (void)user;
    fprintf(stderr, "[fx %d] %s\n", level, message);
    g_errors += level == FX_LOG_ERROR;
}
static int hostWheelCount(void* user) {
    (void)user;
    return 1;
}
/* A burnout on asphalt: full slip, on the ground, a rear wheel; in the host's own (Z-up) world. */
static void hostWheel(void* user, int index, fxWheelContact* out) {
    const Car* car = user;
    (void)index;
    *out = (fxWheelContact){.position = {car->position[0], car->position[1], car->position[2]},
                            .velocity = {car->velocity[0], car->velocity[1], car->velocity[2]},
                            .slip = 1.0f, .surface = FX_SURFACE_ASPHALT, .grounded = 1, .rear = 1};
}
// fx-adapter end

/* ---- camera: right-handed, OpenGL's conventions, in the Z-up world ----------------------- */

static void lookAtZUp(const float eye[3], const float at[3], float m[16]) {
    float f[3], s[3], u[3], n;
    int i;
    for (i = 0; i < 3; ++i) f[i] = at[i] - eye[i];
    n = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= n;
    s[0] = f[1]; s[1] = -f[0]; s[2] = 0.0f; /* f x (0,0,1) */
    n = sqrtf(s[0] * s[0] + s[1] * s[1]);
    s[0] /= n; s[1] /= n;
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

/* One player's half: its viewport and scissor, cleared to the fog colour, the fogged scene. */
static void drawScene(const Player* p, const Fog* fog) {
    float x, y;
    gl.Viewport(p->x, 0, VIEW_WIDTH, HEIGHT);
    gl.Scissor(p->x, 0, VIEW_WIDTH, HEIGHT);
    gl.Enable(GL_SCISSOR_TEST);
    gl.ClearColor(fog->color[0], fog->color[1], fog->color[2], 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_FOG);
    gl.Fogi(GL_FOG_MODE, GL_LINEAR);
    gl.Fogfv(GL_FOG_COLOR, fog->color);
    gl.Fogf(GL_FOG_START, fog->start);
    gl.Fogf(GL_FOG_END, fog->end);
    gl.MatrixMode(GL_PROJECTION);
    gl.LoadMatrixf(p->proj);
    gl.MatrixMode(GL_MODELVIEW);
    gl.LoadMatrixf(p->view);
    gl.Begin(GL_QUADS);
    /* The ground, z = 0, in 2 m tiles: GL fogs by |z_eye| per vertex, which one big quad reaching
     * behind the camera would interpolate into fog over the whole ground. */
    gl.Color3f(0.32f, 0.33f, 0.36f);
    for (x = -60.0f; x < 60.0f; x += 2.0f)
        for (y = -60.0f; y < 60.0f; y += 2.0f) {
            gl.Vertex3f(x, y, 0.0f);
            gl.Vertex3f(x + 2.0f, y, 0.0f);
            gl.Vertex3f(x + 2.0f, y + 2.0f, 0.0f);
            gl.Vertex3f(x, y + 2.0f, 0.0f);
        }
    gl.Color3f(kPost[0], kPost[1], kPost[2]); /* a post south of the wheel, in front of player 1 */
    gl.Vertex3f(0.3f, -1.6f, 0.0f);
    gl.Vertex3f(0.8f, -1.6f, 0.0f);
    gl.Vertex3f(0.8f, -1.6f, 3.0f);
    gl.Vertex3f(0.3f, -1.6f, 3.0f);
    gl.End();
}

/* The whole frame, both players; the smoke too when `plugin` is not null. */
static void drawFrame(const fxApi* fx, fxPlugin* plugin, Player players[PLAYERS], const Fog* fog) {
    int i;
    for (i = 0; i < PLAYERS; ++i) {
        Player* p = &players[i];
        drawScene(p, fog);
        if (plugin) {
            // fx-adapter begin: per-frame (each view's smoke after its scene: camera, fog, viewport, scissor)
            /* The viewport drawScene set places the view; its scissor clips the smoke too. The
             * scene depth: the bound (OSMesa's) framebuffer's, the default depthSource. */
            fxViewDesc v = {.size = sizeof(fxViewDesc), .name = p->name, .eye = {p->eye[0], p->eye[1], p->eye[2]},
                            .nearPlane = NEAR_PLANE, .farPlane = FAR_PLANE, .width = VIEW_WIDTH, .height = HEIGHT,
                            .clipToScissor = 1,
                            .fogMode = FX_FOG_LINEAR, .fogColor = {fog->color[0], fog->color[1], fog->color[2]},
                            .fogStart = fog->start, .fogEnd = fog->end};
            memcpy(v.view, p->view, sizeof v.view);
            memcpy(v.proj, p->proj, sizeof v.proj);
            p->result = fx->renderView(plugin, &v);
            // fx-adapter end
        }
    }
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
    /* Player 1 looks north-west past the post at the wheel; player 2 north-east from the other side. */
    Player players[PLAYERS] = {{"player 1", 0, {2.6f, -3.6f, 1.0f}, {0.0f, 0.5f, 0.6f}, {0}, {0}, 0},
                               {"player 2", VIEW_WIDTH, {-3.2f, -2.4f, 1.8f}, {0.0f, 0.4f, 0.8f}, {0}, {0}, 0}};
    /* The fog begins past the post, so player 1 sees the post in its own colour. */
    const Fog fog = {{0.45f, 0.55f, 0.7f}, 4.0f, 15.0f};
    Car car = {{0.0f, -0.3f, 0.0f}, {0.0f, 0.4f, 0.0f}}; /* creeping north while the wheel spins */
    OSMesaContext context;
    unsigned char *before, *after;
    int step, i, smoke[PLAYERS] = {0, 0}, postPixels = 0, postChanged = 0, glErrors = 0, failed = 0;

    if (argc != 3) {
        fprintf(stderr, "usage: c_host <reactions.yaml> <out.png>\n");
        return 2;
    }
    context = OSMesaCreateContextAttribs(attribs, NULL);
    if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT) || !loadGl()) {
        fprintf(stderr, "c_host: no OSMesa GL 3.3 compatibility context\n");
        return 3;
    }
    for (i = 0; i < PLAYERS; ++i) {
        lookAtZUp(players[i].eye, players[i].at, players[i].view);
        perspective(55.0f * 3.14159265f / 180.0f, (float)VIEW_WIDTH / HEIGHT, NEAR_PLANE, FAR_PLANE, players[i].proj);
    }

    {
        fxStats2 stats = FX_DESC_INIT(fxStats2);
        // fx-adapter begin: setup (the table, the callbacks, a Z-up plugin, its reactions, its GL objects)
        /* Each descriptor is FX_DESC_INIT's C99 form, {.size = sizeof(T)}, with its fields named
         * beside the size: every field not named is zero, its default. */
        const fxApi* fx = fxGetApi(FX_API_VERSION); /* null: the library cannot serve these headers */
        const fxHostCallbacks host = {.size = sizeof(fxHostCallbacks), .user = &car, .getProcAddress = hostProc,
                                      .log = hostLog, .wheelCount = hostWheelCount, .wheel = hostWheel};
        const fxPluginDesc desc = {.size = sizeof(fxPluginDesc), .host = &host, .upAxis = FX_UP_Z};
        fxPlugin* plugin = fx ? fx->create(&desc, NULL) : NULL;
        /* Diagnostics: the plugin logs each through hostLog, with file:line, so no sink is given. */
        if (!plugin || !fx->loadReactions(plugin, argv[1], NULL) || !fx->prepareGl(plugin, NULL)) {
            fprintf(stderr, "c_host: the plugin did not start (library API %#x)\n", (unsigned)fxApiVersion());
            return 1;
        }
        // fx-adapter end

        /* 1.5 s of smoke at 60 Hz while the car creeps north. */
        for (step = 0; step < 90; ++step) {
            for (i = 0; i < 3; ++i) car.position[i] += car.velocity[i] * STEP;
            // fx-adapter begin: per-frame (the simulation step)
            for (i = 0; i < fx->reactionCount(plugin); ++i) fx->continueReaction(plugin, i, STEP, NULL);
            // fx-adapter end
        }

        /* The frame without the plugin's calls, then with them. */
        drawFrame(fx, NULL, players, &fog);
        before = readFrame();
        drawFrame(fx, plugin, players, &fog);
        after = readFrame();
        while (gl.GetError() != GL_NO_ERROR && glErrors < 100) ++glErrors;
        fx->stats2(plugin, &stats);

        // fx-adapter begin: teardown (destroy with the GL context current: it deletes its GL objects)
        fx->destroy(plugin);
        // fx-adapter end

        /* Checks: smoke in each half, none over the post in player 1's half. */
        for (i = 0; i < WIDTH * HEIGHT * 4; i += 4) {
            const int half = (i / 4) % WIDTH / VIEW_WIDTH;
            const int changed = memcmp(before + i, after + i, 3) != 0;
            smoke[half] += changed;
            if (half == 0 && isPost(before + i)) {
                ++postPixels;
                postChanged += changed;
            }
        }
        printf("particles alive %d, drawn %d (over both views)\n", stats.particlesAlive, stats.particlesDrawn);
        for (i = 0; i < PLAYERS; ++i)
            printf("%s: renderView %s; smoke pixels %d of %d (need > %d)\n", players[i].name,
                   fxErrorCodeName(players[i].result), smoke[i], VIEW_WIDTH * HEIGHT, MIN_SMOKE_PIXELS);
        printf("player 1's post: %d pixels, %d changed (need 0)\n", postPixels, postChanged);
        if (!stbi_write_png(argv[2], WIDTH, HEIGHT, 4, after, WIDTH * 4)) {
            fprintf(stderr, "c_host: could not write %s\n", argv[2]);
            failed = 1;
        }
        for (i = 0; i < PLAYERS; ++i)
            if (players[i].result != FX_ERROR_NONE || smoke[i] <= MIN_SMOKE_PIXELS) failed = 1;
        if (failed || postPixels < 500 || postChanged != 0 || g_errors != 0 || glErrors != 0 || stats.apiErrors != 0) {
            printf("c_host: FAIL (plugin errors %d, GL errors %d, API errors %d)\n", g_errors, glErrors,
                   stats.apiErrors);
            failed = 1;
        }
    }

    OSMesaDestroyContext(context);
    free(before);
    free(after);
    if (!failed) printf("c_host: ok\n");
    return failed;
}
