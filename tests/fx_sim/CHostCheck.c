/* A host written in C99 against fx/fx.h alone, compiled as C (the test build's C compiler): the
 * C boundary checked without GL. fxCHostCheck() returns the number of failed checks and writes
 * what failed into `report`. CApiTest.cpp runs it. */
#include <fx/fx.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct Host {
    int errorsLogged;
    char lastError[512];
    float slip;
} Host;

static void* getProc(void* user, const char* name) {
    (void)user;
    (void)name;
    return NULL; /* no GL in this check */
}
static void logMessage(void* user, int level, const char* message) {
    Host* h = (Host*)user;
    if (level == FX_LOG_ERROR) {
        ++h->errorsLogged;
        snprintf(h->lastError, sizeof h->lastError, "%s", message);
    }
}
static int wheelCount(void* user) {
    (void)user;
    return 4;
}
static void wheel(void* user, int index, fxWheelContact* out) {
    const Host* h = (const Host*)user;
    memset(out, 0, sizeof *out);
    out->position[0] = (index & 1) ? 0.8f : -0.8f;
    out->position[2] = (index >= 2) ? 1.3f : -1.3f;
    out->velocity[2] = -1.0f;
    out->rear = index >= 2;
    out->slip = out->rear ? h->slip : 0.0f;
    out->grounded = 1;
    out->surface = FX_SURFACE_ASPHALT;
}

typedef struct Diags {
    int count;
    int firstCode;
    int firstLine;
} Diags;
static void onDiagnostic(void* user, const fxDiagnostic* d) {
    Diags* s = (Diags*)user;
    if (s->count++ == 0) {
        s->firstCode = d->code;
        s->firstLine = d->line;
    }
}

#define CHECK(cond)                                                                      \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            ++failed;                                                                    \
            used += snprintf(report + used, used < capacity ? capacity - used : 0,       \
                             "%s:%d: %s\n", __FILE__, __LINE__, #cond);                  \
        }                                                                                \
    } while (0)

int fxCHostCheck(const char* reactionFile, const char* badReactionFile, char* report, int capacity) {
    int failed = 0, used = 0;
    const fxApi* api = fxGetApi(FX_API_VERSION);
    Host host;
    fxHostCallbacks callbacks = FX_DESC_INIT(fxHostCallbacks);
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    fxPlugin* p;
    int error = -1;
    report[0] = '\0';
    memset(&host, 0, sizeof host);

    CHECK(api != NULL);
    if (!api) return failed;
    CHECK(api->size == sizeof(fxApi));
    CHECK(api->version == FX_API_VERSION && fxApiVersion() == FX_API_VERSION);
    CHECK(fxGetApi(FX_API_VERSION + (1u << 16)) == NULL);  /* another major */
    CHECK(fxGetApi(FX_API_VERSION + 1u) == NULL);          /* a newer minor */
    CHECK(strcmp(fxErrorCodeName(FX_ERROR_BAD_DESCRIPTOR), "BadDescriptor") == 0);
    CHECK(strcmp(fxErrorCodeName(9999), "Unknown") == 0);

    callbacks.user = &host;
    callbacks.getProcAddress = getProc;
    callbacks.log = logMessage;
    callbacks.wheelCount = wheelCount;
    callbacks.wheel = wheel;
    desc.host = &callbacks;

    /* Bad descriptors: a named error, no plugin. A descriptor whose size or version is refused
     * is not read further, so its host is not called: the line goes to stderr. */
    desc.size = sizeof desc - 4;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_BAD_DESCRIPTOR);
    desc.size = sizeof desc;
    desc.apiVersion = FX_API_VERSION + (1u << 16);
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_VERSION_MISMATCH);
    CHECK(host.errorsLogged == 0);
    desc.apiVersion = 0; /* 0 = these headers' version */
    callbacks.log = NULL;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_NULL_ARGUMENT);
    callbacks.log = logMessage;
    callbacks.size = 8;
    CHECK(api->create(&desc, &error) == NULL && error == FX_ERROR_BAD_DESCRIPTOR);
    callbacks.size = sizeof callbacks;
    callbacks.wheel = NULL; /* wheelCount without wheel: each is optional on its own (no wheels) */
    p = api->create(&desc, &error);
    CHECK(p != NULL && error == FX_ERROR_NONE);
    api->destroy(p);
    callbacks.wheel = wheel;
    CHECK(api->create(NULL, &error) == NULL && error == FX_ERROR_NULL_ARGUMENT);

    p = api->create(&desc, &error);
    CHECK(p != NULL && error == FX_ERROR_NONE);
    if (!p) return failed;

    /* A bad file: diagnostics through the sink, with a line; nothing loaded. */
    {
        Diags d = {0, 0, 0};
        fxDiagnosticSink sink;
        sink.user = &d;
        sink.report = onDiagnostic;
        CHECK(!api->loadReactions(p, badReactionFile, &sink));
        CHECK(d.count >= 1 && d.firstCode != FX_ERROR_NONE && d.firstLine > 0);
        CHECK(api->reactionCount(p) == 0);
    }
    CHECK(api->loadReactions(p, reactionFile, NULL));
    CHECK(api->reactionCount(p) >= 1);
    {
        char name[4];
        char whole[128];
        const size_t n = api->reactionName(p, 0, name, sizeof name);
        CHECK(n > 0 && strlen(name) == (n < 3 ? n : 3)); /* truncated, terminated */
        CHECK(api->reactionName(p, 0, whole, sizeof whole) == n && strlen(whole) == n);
        CHECK(api->reactionName(p, 0, NULL, 0) == n);
        CHECK(api->reactionValue(p, 0, "render.technique", whole, sizeof whole) > 0);
        CHECK(api->reactionFileCount(p) == 1);
    }
    /* The schema, as C structs. */
    {
        fxReactionKeyInfo key;
        int i, choices = 0;
        const int keys = api->reactionKeyCount(p);
        CHECK(keys > 10);
        for (i = 0; i < keys; ++i) {
            CHECK(api->reactionKey(p, i, &key) == FX_ERROR_NONE && key.key && key.key[0]);
            if (key.kind == FX_KEY_CHOICE) choices += key.choiceCount;
        }
        CHECK(choices > 0);
        CHECK(api->reactionKey(p, keys, &key) == FX_ERROR_INDEX_OUT_OF_RANGE);
    }
    /* Simulation through the C callbacks: slipping rear wheels emit smoke. */
    {
        int step, r;
        fxStats stats;
        fxParticleCheck check;
        fxReactionStats rs;
        host.slip = 1.0f;
        for (step = 0; step < 60; ++step) {
            for (r = 0; r < api->reactionCount(p); ++r) CHECK(api->continueReaction(p, r, 1.0f / 60.0f, NULL) == FX_ERROR_NONE);
        }
        api->stats(p, &stats);
        CHECK(stats.particlesAlive > 0 && stats.reactions == api->reactionCount(p));
        api->checkParticles(p, &check);
        CHECK(check.alive == stats.particlesAlive && check.nonFinite == 0);
        CHECK(api->reactionStats(p, 0, &rs) == FX_ERROR_NONE && rs.name[0] != '\0' && rs.emitted > 0);
        CHECK(api->reactionStats(p, 99, &rs) == FX_ERROR_INDEX_OUT_OF_RANGE && rs.name[0] == '\0');
        CHECK(api->continueReaction(p, 99, 0.01f, NULL) == FX_ERROR_INDEX_OUT_OF_RANGE);
        CHECK(api->continueReaction(p, 0, (float)NAN, NULL) == FX_ERROR_INVALID_VALUE);
    }
    /* Options: a bad size or value changes nothing. */
    {
        fxRenderOptions o = FX_DESC_INIT(fxRenderOptions), back = FX_DESC_INIT(fxRenderOptions);
        o.techniqueOverride = FX_TECHNIQUE_SOFT;
        o.quarterRes = 1;
        CHECK(api->setRenderOptions(p, &o) == FX_ERROR_NONE);
        o.techniqueOverride = FX_TECHNIQUE_HARD;
        o.size = 4;
        CHECK(api->setRenderOptions(p, &o) == FX_ERROR_BAD_DESCRIPTOR);
        o.size = sizeof o;
        o.techniqueOverride = 77;
        CHECK(api->setRenderOptions(p, &o) == FX_ERROR_INVALID_VALUE);
        api->getRenderOptions(p, &back);
        CHECK(back.techniqueOverride == FX_TECHNIQUE_SOFT && back.quarterRes == 1);
        CHECK(api->setParticleShape(p, 300) == FX_ERROR_INVALID_VALUE && api->particleShape(p) == FX_SHAPE_TRIMMED);
        CHECK(api->setQuarterResEdges(p, -1) == FX_ERROR_INVALID_VALUE);
    }
    /* Views: a bad descriptor is refused before anything is drawn. */
    {
        fxViewDesc v = FX_DESC_INIT(fxViewDesc);
        v.size = 12;
        CHECK(api->renderView(p, &v) == FX_ERROR_BAD_DESCRIPTOR);
        v.size = sizeof v;
        v.handedness = 5;
        CHECK(api->renderView(p, &v) == FX_ERROR_INVALID_VIEW);
        CHECK(api->declarePasses(p, &v, NULL) == FX_ERROR_INVALID_VIEW);
        CHECK(api->renderView(p, NULL) == FX_ERROR_NULL_ARGUMENT);
    }
    {
        fxStats stats;
        api->stats(p, &stats);
        CHECK(stats.apiErrors >= 8);
    }
    CHECK(api->continueReaction(NULL, 0, 0.0f, NULL) == FX_ERROR_NULL_ARGUMENT);
    api->destroy(p);
    api->destroy(NULL);
    return failed;
}
