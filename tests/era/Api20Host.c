/* api20_host: a host compiled against the API 2.0 header (fx_api_2_0.h, frozen), run against this
 * build's library: binary compatibility of the C boundary. A 2.0 host's output structs have no
 * size, so the library must write each one whole and not a byte past it, with the values 2.0
 * gave. Every out-pointer here points into a buffer poisoned with POISON for GUARD bytes past
 * the 2.0 struct; a byte changed there is a write past the host's struct.
 *
 * No GL: every call checked here runs without a context (declareShadowPasses is refused at its
 * view, after it has written its struct). The exit status is the number of failed checks; each
 * failed check prints its line.
 *
 *   api20_host <reactions.yaml>
 */
#include <stdio.h>
#include <string.h>

#include "fx_api_2_0.h" /* not fx/fx.h: this host was built before 2.1 */

#include "EraHost.h" /* CHECK, g_failed, the burnout car */

#define GUARD 64
#define POISON 0xA5

/* An output struct followed by GUARD poisoned bytes, aligned for any of its fields. */
#define GUARDED(T)                            \
    union {                                   \
        T value;                              \
        uint64_t alignWords;                  \
        void* alignPointers;                  \
        double alignDoubles;                  \
        unsigned char bytes[sizeof(T) + GUARD]; \
    }

/* Whether the GUARD bytes after the first `size` bytes of `bytes` are all still POISON. */
static int guardIntact(const unsigned char* bytes, size_t size) {
    size_t i;
    for (i = size; i < size + GUARD; ++i)
        if (bytes[i] != POISON) return 0;
    return 1;
}

static int g_errorsLogged = 0;
static void* hostProc(void* user, const char* name) {
    (void)user;
    (void)name;
    return NULL; /* no GL here */
}
static void hostLog(void* user, int level, const char* message) {
    (void)user;
    if (level == FX_LOG_ERROR) {
        ++g_errorsLogged;
        fprintf(stderr, "[fx error] %s\n", message);
    }
}

int main(int argc, char** argv) {
    fxHostCallbacks callbacks = FX_DESC_INIT(fxHostCallbacks);
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    const fxApi* fx;
    fxPlugin* plugin;
    char name[72];
    int error = -1, step, r, apiErrors;
    GUARDED(fxStats) stats;
    GUARDED(fxParticleCheck) check;
    GUARDED(fxReactionStats) rs;
    GUARDED(fxReactionKeyInfo) key;
    GUARDED(fxRenderOptions) options;
    GUARDED(fxFadeClassCounts) fade;
    GUARDED(fxSmokeShadow) shadow;

    if (argc != 2) {
        fprintf(stderr, "usage: api20_host <reactions.yaml>\n");
        return 100;
    }
    /* The library serves a 2.0 host (its MINOR is at least 0) with the one table it has. */
    fx = fxGetApi(FX_API_VERSION);
    CHECK(fx != NULL);
    if (!fx) return g_failed;
    CHECK(fx->version >> 16 == 2 && (fx->version & 0xFFFFu) >= 1);
    CHECK(fx->size >= sizeof(fxApi)); /* 2.1 appended entries; the 2.0 ones are where they were */

    callbacks.getProcAddress = hostProc;
    callbacks.log = hostLog;
    callbacks.wheelCount = hostWheelCount;
    callbacks.wheel = hostWheel;
    desc.host = &callbacks;
    desc.seed = 7;
    plugin = fx->create(&desc, &error); /* a 2.0-size fxPluginDesc */
    CHECK(plugin != NULL && error == FX_ERROR_NONE);
    if (!plugin) return g_failed;
    CHECK(fx->loadReactions(plugin, argv[1], NULL));
    CHECK(fx->reactionCount(plugin) > 0);
    for (step = 0; step < 60; ++step)
        for (r = 0; r < fx->reactionCount(plugin); ++r)
            CHECK(fx->continueReaction(plugin, r, 1.0f / 60.0f, NULL) == FX_ERROR_NONE);

    /* stats: the counters, whole, nothing past them. */
    memset(stats.bytes, POISON, sizeof stats.bytes);
    fx->stats(plugin, &stats.value);
    CHECK(guardIntact(stats.bytes, sizeof(fxStats)));
    CHECK(stats.value.reactions == fx->reactionCount(plugin));
    CHECK(stats.value.particlesAlive > 0 && stats.value.particleCapacity >= stats.value.particlesAlive);
    CHECK(stats.value.particlesDrawn == 0 && stats.value.reloads == 0 && stats.value.reloadErrors == 0);
    CHECK(stats.value.apiErrors == 0);

    memset(check.bytes, POISON, sizeof check.bytes);
    fx->checkParticles(plugin, &check.value);
    CHECK(guardIntact(check.bytes, sizeof(fxParticleCheck)));
    CHECK(check.value.alive == stats.value.particlesAlive && check.value.capacity == stats.value.particleCapacity);
    CHECK(check.value.nonFinite == 0);

    memset(rs.bytes, POISON, sizeof rs.bytes);
    CHECK(fx->reactionStats(plugin, 0, &rs.value) == FX_ERROR_NONE);
    CHECK(guardIntact(rs.bytes, sizeof(fxReactionStats)));
    fx->reactionName(plugin, 0, name, sizeof name);
    CHECK(strcmp(rs.value.name, name) == 0);
    CHECK(strcmp(rs.value.technique, "soft") == 0 || strcmp(rs.value.technique, "hard") == 0 ||
          strcmp(rs.value.technique, "spherical") == 0 || strcmp(rs.value.technique, "mega") == 0 ||
          strcmp(rs.value.technique, "stateless") == 0);
    CHECK(rs.value.alive == fx->reactionParticlesAlive(plugin, 0) && rs.value.emitted > 0);
    /* A bad index: the struct cleared (name ""), as 2.0 did, and still nothing past it. */
    memset(rs.bytes, POISON, sizeof rs.bytes);
    CHECK(fx->reactionStats(plugin, 99, &rs.value) == FX_ERROR_INDEX_OUT_OF_RANGE);
    CHECK(rs.value.name[0] == '\0' && rs.value.alive == 0 && rs.value.emitted == 0);
    CHECK(guardIntact(rs.bytes, sizeof(fxReactionStats)));

    memset(key.bytes, POISON, sizeof key.bytes);
    CHECK(fx->reactionKeyCount(plugin) > 0);
    CHECK(fx->reactionKey(plugin, 0, &key.value) == FX_ERROR_NONE);
    CHECK(guardIntact(key.bytes, sizeof(fxReactionKeyInfo)));
    CHECK(key.value.key != NULL && key.value.key[0] != '\0' && key.value.kind >= FX_KEY_NUMBER &&
          key.value.kind <= FX_KEY_NAME && key.value.help != NULL && key.value.unit != NULL);
    CHECK(key.value.choiceCount >= 0 && (key.value.choiceCount == 0) == (key.value.choices == NULL));

    /* Options: a 2.0-size fxRenderOptions sets and reads the 2.0 fields; the shape keeps its own
     * setters, and a 2.0 setRenderOptions leaves it as it is. */
    CHECK(fx->setParticleShape(plugin, FX_SHAPE_QUAD) == FX_ERROR_NONE);
    set.techniqueOverride = FX_TECHNIQUE_SOFT;
    set.quarterRes = 1;
    CHECK(fx->setRenderOptions(plugin, &set) == FX_ERROR_NONE);
    CHECK(fx->particleShape(plugin) == FX_SHAPE_QUAD);
    memset(options.bytes, POISON, sizeof options.bytes);
    options.value.size = sizeof(fxRenderOptions);
    fx->getRenderOptions(plugin, &options.value);
    CHECK(guardIntact(options.bytes, sizeof(fxRenderOptions)));
    CHECK(options.value.size == sizeof(fxRenderOptions) && options.value.techniqueOverride == FX_TECHNIQUE_SOFT &&
          options.value.quarterRes == 1 && options.value.bilinearUpsample == 0);
    /* A host that never set the size of a struct it only reads: 2.0 filled it all the same. */
    memset(options.bytes, POISON, sizeof options.bytes);
    options.value.size = 0;
    fx->getRenderOptions(plugin, &options.value);
    CHECK(guardIntact(options.bytes, sizeof(fxRenderOptions)));
    CHECK(options.value.size == 0 && options.value.techniqueOverride == FX_TECHNIQUE_SOFT &&
          options.value.quarterRes == 1);
    CHECK(fx->setParticleShape(plugin, FX_SHAPE_TRIMMED) == FX_ERROR_NONE);
    CHECK(fx->particleShape(plugin) == FX_SHAPE_TRIMMED);

    /* Deprecated, accepted (no effect: the edges since 2.1, fade classification since 2.4), and
     * nothing past the counts. */
    CHECK(fx->setQuarterResEdges(plugin, FX_EDGES_DEPTH_AWARE) == FX_ERROR_NONE);
    CHECK(fx->setFadeClassification(plugin, FX_FADE_CLASSIFICATION_OFF) == FX_ERROR_NONE);
    memset(fade.bytes, POISON, sizeof fade.bytes);
    fx->fadeClassCounts(plugin, &fade.value);
    CHECK(guardIntact(fade.bytes, sizeof(fxFadeClassCounts)));

    /* declareShadowPasses writes its struct (no smoke) before it refuses the missing view. */
    memset(shadow.bytes, POISON, sizeof shadow.bytes);
    CHECK(fx->declareShadowPasses(plugin, NULL, NULL, &shadow.value) == FX_ERROR_NULL_ARGUMENT);
    CHECK(shadow.value.opacity == 0 && shadow.value.worldToShadow[0] == 0.0f && shadow.value.worldToShadow[15] == 0.0f);
    CHECK(guardIntact(shadow.bytes, sizeof(fxSmokeShadow)));

    /* The two refusals (the bad reaction index, the missing view), and only they, were logged and
     * counted. */
    memset(stats.bytes, POISON, sizeof stats.bytes);
    fx->stats(plugin, &stats.value);
    CHECK(guardIntact(stats.bytes, sizeof(fxStats)));
    apiErrors = stats.value.apiErrors;
    CHECK(apiErrors == 2 && g_errorsLogged == 2);

    fx->destroy(plugin); /* no GL object was made */
    printf("api20_host: %s\n", g_failed ? "FAIL" : "ok");
    return g_failed;
}
