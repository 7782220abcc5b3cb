// libFuzzer target for the C table (fx/fx.h): the bytes are a descriptor for create, then a
// sequence of calls with numeric arguments taken from the input (floats of any bit pattern:
// denormals, infinities, NaNs; ints of any value; descriptor sizes of any value). No GL: the
// host's getProcAddress gives nothing, so (GL) calls stop at their checks, which is what is
// fuzzed there. Every call must return without a crash, a sanitizer report or a hang.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <fx/fx.h>

namespace {

struct Bytes {
    const uint8_t* data;
    size_t size;
    size_t at = 0;
    template <class T>
    T take() {
        T v;
        std::memset(&v, 0, sizeof v);
        const size_t n = size - at < sizeof v ? size - at : sizeof v;
        std::memcpy(&v, data + at, n);
        at += n;
        return v;
    }
    bool done() const { return at >= size; }
};

void* noProc(void*, const char*) { return nullptr; }
void quietLog(void*, int, const char*) {}
int wheelCount(void* user) { return *static_cast<int*>(user); }
void wheel(void*, int index, fxWheelContact* out) {
    std::memset(out, 0, sizeof *out);
    out->slip = 1.0f;
    out->grounded = 1;
    out->rear = index & 1;
}

uint32_t color(void*) { return 1; }
uint32_t depth(void*) { return 2; }
uint32_t create(void*, const char*, const fxTargetDesc*) { return 3; }
void add(void*, const char*, const uint32_t*, int, const uint32_t*, int, fxPassCallback cb) {
    if (cb.release) cb.release(cb.user);
}

int g_wheels = 4;  // the shared plugin's wheel count, any int (clamped by the plugin)

const char kBadReaction[] = "reactions:\n  - name: smoke\n    type: wheel_smoke\n    emission: {rate: 1e39}\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const fxApi* api = fxGetApi(FX_API_VERSION);
    Bytes in{data, size};
    int wheels = 4;
    fxHostCallbacks host = FX_DESC_INIT(fxHostCallbacks);
    host.user = &wheels;
    host.getProcAddress = noProc;
    host.log = quietLog;
    host.wheelCount = wheelCount;
    host.wheel = wheel;

    // The descriptor as the input gives it; only its host pointer is ours (null, the callbacks
    // above, or the callbacks with a size and slots from the input), since a host pointer of
    // garbage that passes every check is the host's own undefined behaviour.
    fxPluginDesc desc = in.take<fxPluginDesc>();
    const uint8_t hostChoice = in.take<uint8_t>();
    fxHostCallbacks fuzzed = host;
    fuzzed.size = in.take<uint32_t>();
    desc.host = hostChoice % 3 == 0 ? nullptr : hostChoice % 3 == 1 ? &host : &fuzzed;
    desc.shaderDir = nullptr;
    desc.dataDir = nullptr;
    if (hostChoice & 0x80) {  // mostly a good descriptor, so the calls below get a plugin
        desc.size = sizeof desc;
        desc.apiVersion = 0;
        desc.host = &host;
    }
    int error = -1;
    fxPlugin* made = api->create(&desc, &error);
    if (!made) return 0;
    api->destroy(made);
    api->destroy(made);  // refused: a dead handle
    api->reactionCount(made);

    // One plugin for the whole run with every reaction of the repository: the calls below fuzz
    // the numbers, not the loading (fuzz_reactions does that).
    static fxPlugin* p = [] {
        static fxHostCallbacks h = FX_DESC_INIT(fxHostCallbacks);
        h.user = &g_wheels;
        h.getProcAddress = noProc;
        h.log = quietLog;
        h.wheelCount = wheelCount;
        h.wheel = wheel;
        fxPluginDesc d = FX_DESC_INIT(fxPluginDesc);
        d.host = &h;
        fxPlugin* plugin = fxGetApi(FX_API_VERSION)->create(&d, nullptr);
        fxGetApi(FX_API_VERSION)->loadReactions(plugin, CUBE_SOURCE_DIR "/reactions", nullptr);
        return plugin;
    }();

    fxFrameBuilder frame;
    std::memset(&frame, 0, sizeof frame);
    frame.size = sizeof frame;
    frame.sceneColor = color;
    frame.sceneDepth = depth;
    frame.createTarget = create;
    frame.addPass = add;
    char buffer[32];
    for (int calls = 0; calls < 64 && !in.done(); ++calls) {
        switch (in.take<uint8_t>() % 14) {
        case 0: {
            const int index = in.take<int>();
            float amount = in.take<float>();
            api->continueReaction(p, index, in.take<float>(), (index & 1) ? &amount : nullptr);
            break;
        }
        case 1: {
            float point[3];
            for (float& f : point) f = in.take<float>();
            api->fireReaction(p, "explosion", point);
            break;
        }
        case 2: {
            fxSceneLight light = in.take<fxSceneLight>();
            api->setSceneLight(p, &light);
            break;
        }
        case 3: {
            fxRenderOptions o = in.take<fxRenderOptions>();
            api->setRenderOptions(p, &o);
            break;
        }
        case 4:
            api->setParticleShape(p, in.take<int>());
            api->setQuarterResEdges(p, in.take<int>());
            api->setFadeClassification(p, in.take<int>());
            break;
        case 5: {
            fxViewDesc v = in.take<fxViewDesc>();
            v.name = nullptr;
            if (v.size & 1) v.size = sizeof v;  // past the size check half the time
            api->declarePasses(p, &v, &frame);
            api->renderView(p, &v);
            fxSmokeShadow shadow;
            api->declareShadowPasses(p, &v, &frame, (v.size & 2) ? &shadow : nullptr);
            break;
        }
        case 6: {
            const int index = in.take<int>();
            const size_t capacity = in.take<uint8_t>() % (sizeof buffer + 1);
            api->reactionName(p, index, buffer, capacity);
            api->reactionFile(p, index, buffer, capacity);
            api->reactionValue(p, index, "render.technique", buffer, capacity);
            api->reactionFileAt(p, index, buffer, capacity);
            api->reactionParticlesAlive(p, index);
            fxReactionStats rs;
            api->reactionStats(p, index, &rs);
            fxReactionKeyInfo key;
            api->reactionKey(p, index, &key);
            break;
        }
        case 7:
            // A bad set never replaces the running one; a length past the limit is refused unread.
            api->loadReactionsFromText(p, "fuzz.yaml", kBadReaction, in.take<size_t>() % (sizeof kBadReaction), nullptr);
            api->loadReactionsFromText(p, "fuzz.yaml", kBadReaction, in.take<size_t>() | (size_t(1) << 40), nullptr);
            break;
        case 8:
            g_wheels = in.take<int>();
            break;
        case 9:
            api->prepareGl(p, nullptr);
            break;
        case 10: {
            fxStats s;
            api->stats(p, &s);
            fxParticleCheck c;
            api->checkParticles(p, &c);
            if (c.nonFinite != 0) __builtin_trap();  // a number got through into the pool
            break;
        }
        case 11:
            api->setFadeClassCounting(p, in.take<int>());
            break;
        case 12: {
            fxRenderOptions o = FX_DESC_INIT(fxRenderOptions);
            api->getRenderOptions(p, &o);
            fxFadeClassCounts counts;
            api->fadeClassCounts(p, &counts);
            break;
        }
        default:
            api->clearSceneLight(p);
            break;
        }
    }
    return 0;
}
