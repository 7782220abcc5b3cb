#include "ParticleRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <utility>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "ShaderLoader.h"
#include "reactions/TechniqueTable.h"
#include "base/ApiErrors.h"

namespace fx {
namespace {

// The immediate path (ImmediateFrame) copies and linearises the host's z-buffer only where the
// plugin's passes read it. A pass of this renderer reads the scene depth inside its particles'
// screen bound, grown by the quarter-res tiles' reach (16 px tiles, 6 px border) and aligned to
// the fade classifier's coarse tiles, whose depth ranges it reduces whole. Other frame builders
// read the whole depth anyway: nothing to say to them.
void narrowDepthRead(FrameBuilder& frame, const QuarterResPath::ScreenRect& bound, int width, int height) {
    auto* immediate = dynamic_cast<ImmediateFrame*>(&frame);
    if (!immediate) return;
    DepthRegion r;  // whole
    if (!bound.whole) {
        constexpr int kReach = QuarterResPath::kTileSize + 16, kAlign = FadeClassifier::kCoarseTileSize;
        auto down = [](int v) { return v <= 0 ? 0 : v / kAlign * kAlign; };
        auto up = [](int v, int limit) { return std::min(limit, (v + kAlign - 1) / kAlign * kAlign); };
        r.whole = false;
        r.x0 = down(bound.x0 - kReach);
        r.y0 = down(bound.y0 - kReach);
        r.x1 = up(bound.x1 + kReach, width);
        r.y1 = up(bound.y1 + kReach, height);
    }
    immediate->setNextDepthRegion(r);
}

// FrameBuilder::addPass with the valid ones of up to four read targets (an invalid Target is
// "not read": the opacity map is there only for lit smoke).
void addPassReading(FrameBuilder& frame, const char* name, std::initializer_list<Target> maybeReads,
                    Target write, std::function<void(PassContext&)> execute) {
    Target r[4];
    int n = 0;
    for (Target t : maybeReads) {
        if (t.valid() && n < 4) r[n++] = t;
    }
    switch (n) {
    case 0: frame.addPass(name, {}, {write}, std::move(execute)); break;
    case 1: frame.addPass(name, {r[0]}, {write}, std::move(execute)); break;
    case 2: frame.addPass(name, {r[0], r[1]}, {write}, std::move(execute)); break;
    case 3: frame.addPass(name, {r[0], r[1], r[2]}, {write}, std::move(execute)); break;
    default: frame.addPass(name, {r[0], r[1], r[2], r[3]}, {write}, std::move(execute)); break;
    }
}

const std::vector<ColorStop>& whiteRamp() {
    static const std::vector<ColorStop> kWhite{ColorStop{0.0f, glm::vec4(1.0f)}};
    return kWhite;
}

}  // namespace

ParticleRenderer::ParticleRenderer(ParticleRendererConfig config) : config_(std::move(config)) {}

ParticleRenderer::~ParticleRenderer() {
    if (state_ == State::Unloaded || !privateGlLoaded()) return;  // no GL was ever touched
    // The programs go inside a guard; the atlas, ramp, stream and sampler members delete their
    // objects after this body: deleting changes no state of the host's (none of them is bound
    // once a guard has restored the host's bindings).
    GlStateGuard guard;
    programs_.reset();
    quarter_.reset();
    opacity_.reset();
    classifier_.reset();
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

void ParticleRenderer::log(LogLevel level, const std::string& message) const {
    if (config_.host) config_.host->log(level, message.c_str());
}

bool ParticleRenderer::ensureLoaded() {
    if (state_ != State::Unloaded) return state_ == State::Ready;
    state_ = State::Failed;
    // The plugin's private GL table, filled through the host (never a global loader).
    std::string error;
    if (!loadPrivateGlOrDiagnose(config_.host, &loadDiagnostics_, &error)) {
        log(LogLevel::Error, "fx: particle renderer disabled: " + error);
        return false;
    }

    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);  // every texture we touch goes through a guarded unit
    if (!atlas_.load(config_.dataDir, &error)) {
        log(LogLevel::Error, "fx: particle renderer disabled: " + error);
        loadDiagnostics_.push_back(Diagnostic{ErrorCode::ResourceMissing, "", 0, 0, "", error});
        return false;
    }
    std::vector<std::string> errors;
    // The files of this generation of programs, kept: the classifier built later (when fade
    // classification is turned on) and each contrast power read these, never a later edit.
    sources_ = snapshotShaderReader(shaderReader(config_.shaderDir));
    programs_->build(sources_, &errors);
    FadeClassifier::readSources(sources_);
    quarter_->build(config_.shaderDir, &errors);
    opacity_->build(config_.shaderDir, &errors);
    if (!atlas_.hasNormals() && !normalsWarned_) {
        log(LogLevel::Warning, "fx: lit smoke is drawn as flat cards: " + atlas_.normalsError());
        normalsWarned_ = true;
    }
    // One cause fails every variant built from its file (unlit, lit, each soft program): told once.
    reportLoadErrors(errors);
    if (programs_->usableTechniques(false) == 0) {
        log(LogLevel::Error, "fx: particle renderer disabled: no particle program built");
        return false;
    }
    stream_.create();
    depthSampler_.create();
    ramp_.upload();
    shapeTable_ = atlas_.shapes().packed();
    discTable_ = atlas_.shapes().packed(TrimmedShapes::Clip::Disc);
    discInfo_ = atlas_.shapes().packedInfo(TrimmedShapes::Clip::Disc);
    if (!config_.shaderDir.empty()) shaderStamp_ = shaderStamp();
    state_ = State::Ready;
    return true;
}

uint64_t ParticleRenderer::shaderStamp() const {
    // Size and modification time of every plugin shader in the override folder: the billboard,
    // stateless and mega programs' files and their includes ("particles" or "mega" in the name;
    // the engine's own shaders there are not ours). No file is opened: a FIFO dropped there
    // cannot block the poll.
    uint64_t h = 1469598103934665603ull;
    auto mix = [&](uint64_t v) {
        h ^= v;
        h *= 1099511628211ull;
    };
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(config_.shaderDir, ec)) {
        const std::string name = e.path().filename().string();
        const bool ours = name.find("particles") != std::string::npos || name.find("mega") != std::string::npos;
        if (ours && e.path().extension() == ".glsl") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        for (char c : f.filename().string()) mix(uint64_t(uint8_t(c)));
        mix(uint64_t(std::filesystem::file_size(f, ec)));
        mix(uint64_t(std::filesystem::last_write_time(f, ec).time_since_epoch().count()));
        mix(uint64_t(std::filesystem::status(f, ec).type()));  // a FIFO put in a file's place
    }
    return h;
}

bool ParticleRenderer::reloadShaders(Diagnostics* out, const std::vector<ShaderRebuild>& others) {
    if (config_.shaderDir.empty() || state_ != State::Ready) return false;
    const uint64_t stamp = shaderStamp();
    if (stamp == shaderStamp_) return false;
    shaderStamp_ = stamp;  // one attempt (and one message) per edit
    GlStateGuard guard;
    auto programs = std::make_unique<ParticlePrograms>();
    auto quarter = std::make_unique<QuarterResPath>();
    auto opacity = std::make_unique<SmokeOpacityMap>();
    std::vector<std::string> errors;
    const ShaderReader sources = snapshotShaderReader(shaderReader(config_.shaderDir));
    programs->build(sources, &errors);
    programs->buildPowers(programs_->builtPowers(), &errors);  // the contrast powers drawn so far
    quarter->build(config_.shaderDir, &errors);
    opacity->build(config_.shaderDir, &errors);
    // The classifier's programs are built even when classification is off, to check its files:
    // an edit that breaks them is refused now, not when classification is turned on.
    auto classifier = std::make_unique<FadeClassifier>();
    classifier->build(sources, &errors);
    if (classifier_) classifier->programs().buildPowers(classifier_->programs().builtPowers(), &errors);
    ShaderErrorLog unique;
    for (const std::string& e : errors) unique.add(e);
    // The other techniques' programs (mega, stateless) in the same transaction: all go live or
    // none, and one edit gives one line, whichever technique's file it broke.
    std::vector<std::function<void()>> commits;
    for (const ShaderRebuild& other : others) {
        if (std::function<void()> commit = other(&unique)) commits.push_back(std::move(commit));
    }
    if (!unique.empty()) {
        // The new programs are dropped (their destructors delete what did build; each other
        // renderer dropped its own); the running ones stay, so the smoke on screen does not change.
        log(LogLevel::Error, "fx: particle shaders in " + config_.shaderDir +
                                 " changed but do not build; the last good programs are kept:\n" + unique.text());
        if (out) addShaderDiagnostics(unique.text(), out);
        return false;
    }
    programs_ = std::move(programs);
    quarter_ = std::move(quarter);
    opacity_ = std::move(opacity);
    if (classifier_) classifier_ = std::move(classifier);
    sources_ = sources;
    for (const std::function<void()>& commit : commits) commit();
    classifierFailed_ = false;  // a classifier that failed to build gets another try with the new files
    log(LogLevel::Info, "fx: particle shaders reloaded from " + config_.shaderDir);
    return true;
}

bool ParticleRenderer::ensureClassifier() {
    if (classifier_) return true;
    if (classifierFailed_) return false;
    GlStateGuard guard;
    auto classifier = std::make_unique<FadeClassifier>();
    std::vector<std::string> errors;
    classifier->build(sources_, &errors);  // the files of the running programs
    if (!errors.empty() || !classifier->ok()) {
        std::string text = "fx: fade classification is off: its programs did not build";
        for (const std::string& e : errors) text += "\n" + e;
        log(LogLevel::Error, text);
        classifierFailed_ = true;
        return false;
    }
    classifier_ = std::move(classifier);
    return true;
}

bool ParticleRenderer::prepare(Diagnostics* out, const std::vector<int>& powerSteps) {
    const bool ready = ensureLoaded();
    if (ready && !powerSteps.empty()) {
        // The soft programs of the contrast powers the loaded reactions draw with, now rather
        // than at their first visible particle (each power is tried once: reported once).
        GlStateGuard guard;
        std::vector<std::string> errors;
        programs_->buildPowers(powerSteps, &errors);
        // A power's build fails for the cause that failed the soft programs above: not told twice.
        reportLoadErrors(errors);
    }
    if (out) out->insert(out->end(), loadDiagnostics_.begin(), loadDiagnostics_.end());
    return ready && loadDiagnostics_.empty();
}

bool ParticleRenderer::sizesAgree(PassContext& ctx, const ViewInfo& view, Target first, Target second) {
    const int w = ctx.width(first), h = ctx.height(first);
    const bool secondOk = !second.valid() || (ctx.width(second) == w && ctx.height(second) == h);
    if (w == view.width && h == view.height && secondOk) return true;
    if (config_.errors) {
        std::string what = "the scene targets are " + std::to_string(w) + "x" + std::to_string(h);
        if (second.valid()) {
            what += " and " + std::to_string(ctx.width(second)) + "x" + std::to_string(ctx.height(second));
        }
        what += ", ViewInfo " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                "; they must be equal; nothing drawn";
        config_.errors->refuse(ErrorCode::SizeMismatch, "particle pass", what);
    }
    return false;
}

std::shared_ptr<ParticleRenderer::ViewRecord> ParticleRenderer::acquireRecord() {
    // A record whose passes the host has dropped is only held here: reuse it (and its buffers).
    for (const std::shared_ptr<ViewRecord>& r : records_) {
        if (r.use_count() == 1) return r;
    }
    records_.push_back(std::make_shared<ViewRecord>());
    return records_.back();
}

int ParticleRenderer::declarePasses(const ViewInfo& view, FrameBuilder& frame,
                                    const ParticleBatch* batches, int batchCount,
                                    const RenderOptions& options) {
    // The opacity map declareShadowPasses declared for this frame (taken now: a Target is valid
    // for one frame only).
    SmokeShadow shadow = pendingShadow_;
    pendingShadow_ = SmokeShadow{};
    if (state_ == State::Failed) return 0;
    std::shared_ptr<ViewRecord> record = acquireRecord();
    record->view = view;
    record->view.name = "";  // the host's string is not ours to keep
    record->shape = shape_;

    // Until something is visible nothing is loaded: a scene without smoke never compiles a shader.
    const uint32_t allTechniques = techniqueBit(Technique::Hard) | techniqueBit(Technique::Soft) |
                                   techniqueBit(Technique::Spherical);
    const bool wasReady = state_ == State::Ready;
    bool quarterRes = options.quarterRes && (!wasReady || quarter_->ok());
    uint32_t usable = wasReady ? programs_->usableTechniques(quarterRes) : allTechniques;
    builder_.build(view, batches, batchCount, options.techniqueOverride, usable, &record->list);
    if (record->list.particleCount() == 0) return 0;
    if (!wasReady) {
        if (!ensureLoaded()) return 0;
        quarterRes = options.quarterRes && quarter_->ok();
        if (programs_->usableTechniques(quarterRes) != usable) {
            usable = programs_->usableTechniques(quarterRes);
            builder_.build(view, batches, batchCount, options.techniqueOverride, usable, &record->list);
        }
    }
    if (options.quarterRes && !quarterRes && !quarterFallbackLogged_) {
        log(LogLevel::Warning, "fx: quarter-res programs failed to build; drawing particles at full res");
        quarterFallbackLogged_ = true;
    }
    const int drawn = record->list.particleCount();
    if (drawn == 0) return 0;

    setRampRows(batches, batchCount);

    // Lit smoke: the opacity map the host had declared for this frame, else one of our own.
    record->lit = light_.on;
    record->opacity = Target{};
    if (light_.on && !shadow.valid()) shadow = declareOpacityPass(view, frame, batches, batchCount);
    if (light_.on && shadow.valid()) {
        record->opacity = shadow.opacity;
        record->worldToShadow = shadow.worldToShadow;
    }
    const Target opacity = record->opacity;

    const Target color = frame.sceneColor();
    if (!(classify_ && countClasses_)) counts_ = FadeClassCounts{};
    bool spheres = false;
    for (const DrawBatch& batch : record->list.batches) spheres = spheres || techniqueRow(batch.technique, false).raySphere;
    const QuarterResPath::Footprint footprint =
        spheres ? QuarterResPath::Footprint::Box : QuarterResPath::Footprint::Billboard;
    if (!quarterRes) {
        const Target depth = record->list.needsSceneDepth ? frame.sceneDepth() : Target{};
        QuarterResPath::ScreenRect bound;  // whole
        if (depth.valid() && dynamic_cast<ImmediateFrame*>(&frame)) {
            bound = QuarterResPath::screenRect(view, record->list.instances.data(), record->list.particleCount(),
                                               nullptr, footprint);
        }
        // Fade classification: the scene depth's range per tile, read by the classified programs.
        Target tiles, coarse;
        if (classify_ && depth.valid() && ensureClassifier()) {
            tiles = frame.createTarget(FadeClassifier::kTileTarget,
                                       FadeClassifier::tileTargetDesc(view.width, view.height, false));
            coarse = frame.createTarget(FadeClassifier::kCoarseTarget,
                                        FadeClassifier::tileTargetDesc(view.width, view.height, true));
            narrowDepthRead(frame, bound, view.width, view.height);
            frame.addPass(FadeClassifier::kPass, {depth}, {tiles, coarse},
                          [this, record, depth, tiles, coarse](PassContext& ctx) {
                              if (!sizesAgree(ctx, record->view, depth, Target{})) return;
                              GlStateGuard guard;
                              DebugGroup group(FadeClassifier::kPass);
                              classifier_->buildTiles(ctx, depth, tiles, coarse);
                          });
        }
        const bool count = tiles.valid() && countClasses_;
        narrowDepthRead(frame, bound, view.width, view.height);
        addPassReading(frame, kFullResPass, {depth, opacity, tiles, coarse}, color,
                       [this, record, depth, color, opacity, tiles, coarse, count](PassContext& ctx) {
                           if (!sizesAgree(ctx, record->view, color, depth)) return;
                           GlStateGuard guard(record->view.depth);  // z-tested against the host's z-buffer
                           DebugGroup group(kFullResPass);
                           ctx.bindForDraw(color);
                           const uint32_t tileTexture = tiles.valid() ? ctx.texture(tiles, 0).name : 0;
                           const uint32_t coarseTexture = coarse.valid() ? ctx.texture(coarse, 0).name : 0;
                           drawBatches(*record, depth.valid() ? ctx.texture(depth, 0).name : 0, false, false,
                                       opacity.valid() ? ctx.texture(opacity, 0).name : 0, tileTexture,
                                       coarseTexture);
                           if (count) {
                               counts_ = classifier_->count(record->list.batches, stream_, record->view, tileTexture,
                                                            coarseTexture);
                           }
                       });
        return drawn;
    }

    // Where the smoke can be: the quarter-res passes' fixed costs stay inside it.
    record->rect = QuarterResPath::screenRect(view, record->list.instances.data(), record->list.particleCount(),
                                              &record->tiles, footprint);
    const Target depth = frame.sceneDepth();
    const Target halfDepth = frame.createTarget(QuarterResPath::kDepthTarget,
                                                QuarterResPath::depthTargetDesc());
    // Under reversed-Z the half-res particles are z-tested too (QuarterResPath::beginQuarter).
    const bool halfZ = view.depth == DepthConvention::ReversedZ && quarter_->halfZOk();
    const Target halfColor = frame.createTarget(QuarterResPath::kColorTarget,
                                                QuarterResPath::colorTargetDesc(halfZ));
    narrowDepthRead(frame, record->rect, view.width, view.height);
    frame.addPass(QuarterResPath::kDownsamplePass, {depth}, {halfDepth},
                  [this, record, depth, halfDepth](PassContext& ctx) {
                      // Only what this pass declared may be touched: the scene depth.
                      if (!sizesAgree(ctx, record->view, depth, Target{})) return;
                      GlStateGuard guard;
                      DebugGroup group(QuarterResPath::kDownsamplePass);
                      quarter_->downsampleDepth(ctx, depth, halfDepth, record->rect, record->tiles);
                  });
    auto quarterPass = [this, record, halfDepth, halfColor, halfZ, opacity](PassContext& ctx) {
        GlStateGuard guard(record->view.depth);  // z-tested against the half z written for this view
        DebugGroup group(QuarterResPath::kQuarterPass);
        const bool zTested = quarter_->beginQuarter(ctx, halfColor, record->rect, record->tiles,
                                                    halfZ ? halfDepth : Target{}, halfZ ? &record->view : nullptr);
        drawBatches(*record, ctx.texture(halfDepth, 0).name, true, zTested,
                    opacity.valid() ? ctx.texture(opacity, 0).name : 0);
    };
    addPassReading(frame, QuarterResPath::kQuarterPass, {halfDepth, opacity}, halfColor,
                   quarterPass);
    const bool bilinear = options.bilinearUpsample;
    // Mixed resolution: the edge pixels redrawn at full res (the full-res programs' linear-depth
    // test: HardLinearDepth for hard), depth-tested against the mask beginEdges wrote.
    Target edgeColor;
    if (edges_ == QuarterResEdges::MixedResolution && quarter_->mixedOk() && !bilinear) {
        edgeColor = frame.createTarget(QuarterResPath::kEdgeTarget, QuarterResPath::edgeTargetDesc());
        narrowDepthRead(frame, record->rect, view.width, view.height);
        addPassReading(frame, QuarterResPath::kEdgePass, {halfDepth, depth, opacity}, edgeColor,
                       [this, record, edgeColor, halfDepth, depth, opacity](PassContext& ctx) {
                           GlStateGuard guard(record->view.depth);
                           DebugGroup group(QuarterResPath::kEdgePass);
                           quarter_->beginEdges(ctx, edgeColor, halfDepth, depth, record->rect, record->tiles,
                                                record->view);
                           drawBatches(*record, ctx.texture(depth, 0).name, true, true,
                                       opacity.valid() ? ctx.texture(opacity, 0).name : 0);
                       });
    }
    narrowDepthRead(frame, record->rect, view.width, view.height);
    addPassReading(frame, QuarterResPath::kCompositePass, {halfColor, halfDepth, depth, edgeColor}, color,
                   [this, record, color, halfColor, halfDepth, depth, bilinear, edgeColor](PassContext& ctx) {
                       GlStateGuard guard;
                       DebugGroup group(QuarterResPath::kCompositePass);
                       quarter_->composite(ctx, color, halfColor, halfDepth, depth, bilinear, record->rect,
                                           record->tiles, edgeColor);
                   });
    return drawn;
}

void ParticleRenderer::setRampRows(const ParticleBatch* batches, int batchCount) {
    rampInputs_.clear();
    for (int b = 0; b < batchCount; ++b) {
        rampInputs_.push_back(batches[b].desc ? &batches[b].desc->particle.colorRamp : &whiteRamp());
    }
    ramp_.setRows(rampInputs_);
}

}  // namespace fx
