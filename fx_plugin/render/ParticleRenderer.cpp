#include "ParticleRenderer.h"

#include <algorithm>
#include <functional>
#include <utility>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "PassDeclaration.h"
#include "ScreenTiles.h"
#include "ShaderLoader.h"
#include "reactions/TechniqueTable.h"
#include "base/ApiErrors.h"

namespace fx {
namespace {

// The passes' SizeMismatch, counted by the plugin's ApiErrors (none: not counted).
SizeMismatchReport sizeMismatchTo(ApiErrors* errors) {
    if (!errors) return {};
    return [errors](const std::string& what) { errors->refuse(ErrorCode::SizeMismatch, "particle pass", what); };
}

}  // namespace

ParticleRenderer::ParticleRenderer(RendererConfig config, ProgramCache& programs)
    : config_(std::move(config)),
      draw_(programs),
      fullRes_(draw_, sizeMismatchTo(config_.errors)),
      quarter_(draw_, sizeMismatchTo(config_.errors)),
      tiled_(draw_, sizeMismatchTo(config_.errors)) {
    tiled_.setStageLog([this](const std::string& line) { log(LogLevel::Info, line); });
    draw_.setJobs(config_.jobs);
}

ParticleRenderer::~ParticleRenderer() {
    if (state_ == State::Unloaded || !privateGlLoaded()) return;  // no GL was ever touched
    // The quarter-res set goes inside a guard; the atlas, ramp, stream and sampler members delete
    // their objects after this body: deleting changes no state of the host's (none of them is
    // bound once a guard has restored the host's bindings). The programs are Renderers'.
    GlStateGuard guard;
    quarter_.swapPrograms(nullptr);
}

void ParticleRenderer::reportLoadErrors(const std::vector<std::string>& errors) {
    std::string fresh;
    for (const std::string& e : errors) {
        const std::string lines = loadErrors_.add(e);
        if (!lines.empty()) fresh += (fresh.empty() ? "" : "\n") + lines;
    }
    if (!fresh.empty()) {
        log(LogLevel::Error, "fx: shader build failed:\n" + fresh);
        addShaderDiagnostics(fresh, &loadDiagnostics_);
    }
}

bool ParticleRenderer::ensureLoaded() {
    if (state_ != State::Unloaded) return state_ == State::Ready;
    state_ = State::Failed;
    if (!loadGlFor(config_, "particle renderer", &loadDiagnostics_)) return false;
    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);  // every texture we touch goes through a guarded unit
    std::string error;
    if (!draw_.loadAtlas(config_.dataDir, &error)) {
        log(LogLevel::Error, "fx: particle renderer disabled: " + error);
        loadDiagnostics_.push_back(Diagnostic{ErrorCode::ResourceMissing, "", 0, 0, "", error});
        return false;
    }
    std::vector<std::string> errors;
    draw_.programs().build(ProgramCache::techniqueKeys(), &errors);
    draw_.programs().build(ProgramCache::passKeys(), &errors);
    bindPassPrograms();
    if (!draw_.atlas().hasNormals() && !normalsWarned_) {
        log(LogLevel::Warning, "fx: lit smoke is drawn as flat cards: " + draw_.atlas().normalsError());
        normalsWarned_ = true;
    }
    // One cause fails every variant built from its file (unlit, lit, each soft program): told once.
    reportLoadErrors(errors);
    if (draw_.programs().usableTechniques(false) == 0) {
        log(LogLevel::Error, "fx: particle renderer disabled: no particle program built");
        return false;
    }
    draw_.create();
    if (const char* problem = TiledPath::cpuListLimitProblem()) log(LogLevel::Warning, problem);
    if (const char* problem = TileSort::orderLimitProblem()) log(LogLevel::Warning, problem);
    if (const char* problem = TiledPath::deferBinsProblem()) log(LogLevel::Warning, problem);
    if (const char* problem = TiledPath::gpuBinsProblem()) log(LogLevel::Warning, problem);
    if (const char* problem = TiledPath::gatherInPassProblem()) log(LogLevel::Warning, problem);
    if (const char* problem = QuarterResPath::choiceInPassProblem()) log(LogLevel::Warning, problem);
    if (!config_.shaderDir.empty()) shaderStamp_ = shaderStamp(config_.shaderDir);
    state_ = State::Ready;
    return true;
}

bool ParticleRenderer::shadersChanged() {
    if (config_.shaderDir.empty() || state_ != State::Ready) return false;
    const uint64_t stamp = shaderStamp(config_.shaderDir);
    if (stamp == shaderStamp_) return false;
    shaderStamp_ = stamp;  // one attempt (and one message) per edit
    return true;
}

void ParticleRenderer::bindPassPrograms() {
    quarter_.programs().bind(draw_.programs());
    opacity_.bind(draw_.programs());
    if (TiledPath::available()) tiled_.bind(draw_.programs());
}


bool ParticleRenderer::prepare(Diagnostics* out, const std::vector<int>& powerSteps, bool quarterRes, bool tiled) {
    const bool ready = ensureLoaded();
    if (ready) {
        // The soft programs of the contrast powers the loaded reactions draw with, now rather
        // than at their first visible particle (each key is tried once: reported once); with
        // quarter res on, the quarter-res builds too.
        GlStateGuard guard;
        std::vector<ProgramCache::Key> keys;
        if (quarterRes) keys = ProgramCache::halfResKeys();
        for (int s : powerSteps) {
            ProgramCache::addDrawKeys(Technique::Soft, 0.5f * float(s), false, &keys);
            if (quarterRes) ProgramCache::addDrawKeys(Technique::Soft, 0.5f * float(s), true, &keys);
        }
        tiled = tiled && TiledPath::available();
        if (tiled) {
            const std::vector<ProgramCache::Key> t = ProgramCache::tiledKeys();
            keys.insert(keys.end(), t.begin(), t.end());
        }
        std::vector<std::string> errors;
        draw_.programs().build(keys, &errors);
        if (tiled) tiled_.bind(draw_.programs());
        // A power's build fails for the cause that failed the soft programs above: not told twice.
        reportLoadErrors(errors);
    }
    if (out) out->insert(out->end(), loadDiagnostics_.begin(), loadDiagnostics_.end());
    return ready && loadDiagnostics_.empty();
}

void ParticleRenderer::ensureDrawPrograms(const ParticleView& record, bool quarterRes, bool tiled) {
    drawKeys_.clear();
    if (tiled) drawKeys_ = ProgramCache::tiledKeys();
    for (const DrawBatch& batch : record.list.batches) {
        ProgramCache::addDrawKeys(batch.technique, batch.contrastPower, quarterRes, &drawKeys_);
    }
    bool missing = false;
    for (const ProgramCache::Key& k : drawKeys_) missing = missing || !draw_.programs().tried(k);
    if (!missing) return;
    GlStateGuard guard;
    std::vector<std::string> errors;
    const int built = draw_.programs().build(drawKeys_, &errors);
    if (tiled) tiled_.bind(draw_.programs());
    if (!frameBuildLogged_) {
        log(LogLevel::Warning, "fx: " + std::to_string(built) +
                                   " particle program(s) built while declaring a frame: call prepareGl after "
                                   "changing options or reactions to build them up front");
        frameBuildLogged_ = true;
    }
    reportLoadErrors(errors);
}

void ParticleRenderer::settleLists() {
    for (const std::shared_ptr<ParticleView>& record : records_) {
        if (!record->list.gatherPending()) continue;
        if (record.use_count() > 1 && !record->drawn) {
            record->list.settle(config_.jobs);
            ++listsSettled_;
        } else {
            // No pass left to draw it: culled and released, or drawn (a host's graph may hold its
            // passes until the next frame, as the engine's does). A pass the host runs again
            // after this draws nothing.
            record->list.clear();
        }
    }
}

int ParticleRenderer::declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                    int batchCount, const FrameSettings& settings) {
    // The opacity map declareShadowPasses declared for this frame (taken now: a Target is valid
    // for one frame only). Not by the immediate path's own frame (renderView): that map is a
    // target of the host's frame graph, which this frame cannot read, and it stays for the
    // host's own next declarePasses; renderView declares a map of its own below.
    SmokeShadow shadow;
    if (!dynamic_cast<ImmediateFrame*>(&frame)) {
        shadow = pendingShadow_;
        pendingShadow_ = SmokeShadow{};
    }
    if (state_ == State::Failed) return 0;
    std::shared_ptr<ParticleView> record = reuseRecord(records_);
    record->view = view;
    record->view.name = "";  // the host's string is not ours to keep
    record->settings = settings;
    record->reversedZ = view.depth == DepthConvention::ReversedZ;
    record->drawn = false;

    // Until something is visible nothing is loaded: a scene without smoke never compiles a shader.
    const uint32_t mine = techniquesDrawnBy(DrawnBy::Billboards);
    const RenderOptions& options = settings.options;
    const bool wasReady = state_ == State::Ready;
    bool quarterRes = options.quarterRes && (!wasReady || quarter_.ok());
    uint32_t usable = wasReady ? draw_.programs().usableTechniques(quarterRes) & mine : mine;
    // A view the tiled path will likely draw, of enough particles, is sorted back to front on the
    // GPU (TileSort.h): its list is built without the CPU's sort, which order() below does where
    // another path draws it after all (spheres under an orthographic projection; a view it cannot
    // bin), at the cost of a copy of the list.
    int alive = 0;
    for (int b = 0; b < batchCount; ++b) alive += batches[b].pool ? batches[b].pool->alive() : 0;
    const bool deferOrder = !(options.quarterRes && options.quarterResAlways) && batchCount <= TiledPath::kMaxBatches &&
                            TiledPath::flatW(view.proj) && tiled_.ordersOnGpu(alive) && TiledPath::wanted(options);
    // Such a view's particles are only culled and counted here, where the GPU bins them too: the
    // tiled path's first pass writes them straight into its storage buffer (DrawList::gatherPending),
    // while the GPU runs the host's scene. Every other way settles the list first (below,
    // TiledPath::declare, DrawListBuilder::order).
    const bool deferGather = deferOrder && TiledPath::gpuBins() && TiledPath::gatherInPass();
    builder_.build(view, batches, batchCount, options.techniqueOverride, usable, &record->list, config_.jobs,
                   deferOrder, deferGather);
    if (record->list.particleCount() == 0) return 0;
    if (!wasReady) {
        if (!ensureLoaded()) return 0;
        quarterRes = options.quarterRes && quarter_.ok();
        if ((draw_.programs().usableTechniques(quarterRes) & mine) != usable) {
            usable = draw_.programs().usableTechniques(quarterRes) & mine;
            builder_.build(view, batches, batchCount, options.techniqueOverride, usable, &record->list, config_.jobs,
                           deferOrder, deferGather);
        }
    }
    if (options.quarterRes && !quarterRes && !quarterFallbackLogged_) {
        log(LogLevel::Warning, "fx: quarter-res programs failed to build; drawing particles at full res");
        quarterFallbackLogged_ = true;
    }
    const int drawn = record->list.particleCount();
    if (drawn == 0) return 0;
    // From quarter res back to full res: a technique whose quarter-res program failed was left
    // out of the list; at full res it draws. False where nothing is left to draw.
    auto toFullRes = [&]() {
        quarterRes = false;
        if ((draw_.programs().usableTechniques(false) & mine) == usable) return true;
        usable = draw_.programs().usableTechniques(false) & mine;
        builder_.build(view, batches, batchCount, options.techniqueOverride, usable, &record->list, config_.jobs,
                       deferOrder, deferGather);
        return record->list.particleCount() > 0;
    };
    // Quarter res is weighed against the full-resolution raster pass. Where the tiled path draws
    // the view it costs less than either, for a truer picture (H200, docs/results.md session 26:
    // frame / hard in the standard, fill and 4K scenes, soft+tiled 0.711, 0.402, 0.731 against
    // soft+quarter's 0.793, 0.505, 0.803; spheres 0.798, 0.504, 0.809 against 1.164, 0.998,
    // 1.079; 56 against 51 dB): such a view takes it, and its bound is not worked out.
    // quarterResAlways keeps quarter res, and so do tiled programs that failed to build (not yet
    // tried: ensureDrawPrograms builds them below).
    const bool tiledBuilds = !draw_.programs().tried(ProgramCache::Key::of(ProgramCache::TiledShade)) || tiled_.ok();
    if (quarterRes && !options.quarterResAlways && tiledBuilds && TiledPath::wanted(options) &&
        TiledPath::canDraw(*record)) {
        if (!toFullRes()) return 0;
    }
    // Where the smoke can be (the quarter-res passes' fixed costs stay inside it), and whether its
    // overdraw pays for them; if not, this view is drawn at full res. In a host's frame graph the
    // choice waits for the view's first pass (QuarterResPath::settle): its passes and the full-res
    // one are declared, and the bound is worked out while the GPU runs the host's scene instead of
    // before the host has sent it (on a GPU at 1,000 particles, 65 us of a 1.4 ms frame: docs/
    // results.md, session 29). Not where full res would draw a list of its own (toFullRes), nor in
    // renderView's frame, whose depth copy is cut to the rect before any pass runs.
    const bool waits = quarterRes && !options.quarterResAlways && QuarterResPath::choiceInPass() &&
                       !dynamic_cast<ImmediateFrame*>(&frame) &&
                       (draw_.programs().usableTechniques(false) & mine) == usable;
    if (quarterRes && !waits) {
        record->list.settle(config_.jobs);
        quarter_.bound(*record);
        if (!options.quarterResAlways && !quarterResPays(record->rect, record->tiles) && !toFullRes()) return 0;
    }
    record->quarter = waits ? ParticleView::Quarter::Pending
                            : quarterRes ? ParticleView::Quarter::Yes : ParticleView::Quarter::No;
    const bool pending = record->quarter == ParticleView::Quarter::Pending;
    // Tiled (TiledPath.h): a full-resolution view it can draw, in a context with compute shaders.
    const bool tiled = !quarterRes && TiledPath::wanted(options) && TiledPath::canDraw(*record);
    ensureDrawPrograms(*record, quarterRes, tiled);
    if (pending) ensureDrawPrograms(*record, false, false);

    draw_.ramp().setRows(batches, batchCount);

    // Lit smoke: the opacity map the host had declared for this frame, else one of our own.
    const LightState& light = settings.light;
    record->opacity = Target{};
    if (light.on && !shadow.valid()) shadow = declareOpacityPass(view, frame, batches, batchCount, light);
    if (light.on && shadow.valid()) {
        record->opacity = shadow.opacity;
        record->worldToShadow = shadow.worldToShadow;
    }
    if (!quarterRes && tiled && tiled_.ok()) {
        // The GPU sorts the particles where ordersOnGpu says so; else the order goes in here.
        if (!tiled_.ordersOnGpu(record->list.particleCount())) builder_.order(view, &record->list, config_.jobs);
        // False for a view it cannot bin (a particle with no bound): that one falls through to
        // full res. A view binned in its pass falls back there: its order put in place, then the
        // full-resolution draw.
        auto fallback = [this, record](PassContext& ctx, Target color, Target depth, const SceneDepthDecode& decode,
                                       Target opacity) {
            builder_.order(record->view, &record->list, config_.jobs);
            fullRes_.execute(ctx, *record, color, depth, decode, opacity);
        };
        if (tiled_.declare(frame, record, config_.jobs, fallback)) return record->list.particleCount();
    }
    builder_.order(view, &record->list, config_.jobs);  // nothing where the order is in place
    if (quarterRes) {
        quarter_.declare(frame, record);
        if (pending) fullRes_.declare(frame, record, [this, record] { return !quarter_.settle(*record); });
    } else {
        fullRes_.declare(frame, record);
    }
    return record->list.particleCount();
}

}  // namespace fx
