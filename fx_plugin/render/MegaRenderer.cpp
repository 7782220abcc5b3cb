#include "MegaRenderer.h"

#include <algorithm>
#include <functional>
#include <utility>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ShaderLoader.h"
#include "base/ApiErrors.h"
#include "reactions/TechniqueTable.h"

namespace fx {
namespace {

TargetDesc megaTarget(float scale, TargetFormat format) {
    TargetDesc d;
    d.scale = scale;
    d.format = format;
    d.linearFilter = false;  // every read is a texelFetch
    return d;
}

// The passes' SizeMismatch, counted by the plugin's ApiErrors (none: not counted).
SizeMismatchReport sizeMismatchTo(ApiErrors* errors) {
    if (!errors) return {};
    return [errors](const std::string& what) { errors->refuse(ErrorCode::SizeMismatch, "mega pass", what); };
}

}  // namespace

MegaRenderer::MegaRenderer(RendererConfig config, ProgramCache& programs)
    : config_(std::move(config)), programs_(programs), passes_(sizeMismatchTo(config_.errors)) {}

MegaRenderer::~MegaRenderer() {
    if (state_ == State::Unloaded || !privateGlLoaded()) return;  // no GL was ever touched
    GlStateGuard guard;
    passes_.releaseGl();
}

bool MegaRenderer::ensureLoaded() {
    if (state_ != State::Unloaded) return state_ == State::Ready;
    state_ = State::Failed;
    if (!loadGlFor(config_, "mega-particles", &loadDiagnostics_)) return false;
    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);
    std::vector<std::string> errors;
    programs_.build(ProgramCache::megaKeys(), &errors);
    auto programs = std::make_unique<MegaPrograms>();
    programs->bind(programs_);
    // The blur and shade programs share fs_mega_blur.glsl, and four programs share
    // vs_particles_fullscreen.glsl: one cause is told once.
    ShaderErrorLog unique;
    for (const std::string& e : errors) unique.add(e);
    if (!unique.empty()) {
        log(LogLevel::Error, "fx: mega-particle shader build failed:\n" + unique.text());
        addShaderDiagnostics(unique.text(), &loadDiagnostics_);
    }
    if (!programs->ok()) return false;
    passes_.create(std::move(programs));
    state_ = State::Ready;
    return true;
}

void MegaRenderer::programsSwapped() {
    if (state_ != State::Ready) return;
    auto next = std::make_unique<MegaPrograms>();
    next->bind(programs_);
    passes_.swapPrograms(std::move(next));  // the old set holds names of the old cache: dropped
}

bool MegaRenderer::prepare(Diagnostics* out) {
    const bool ok = ensureLoaded();
    if (out) out->insert(out->end(), loadDiagnostics_.begin(), loadDiagnostics_.end());
    return ok;
}

int MegaRenderer::declarePasses(const ViewInfo& view, FrameBuilder& frame, const ParticleBatch* batches,
                                int batchCount, const FrameSettings& settings) {
    if (state_ == State::Failed) return 0;
    std::shared_ptr<MegaCloud> record = reuseRecord(records_);
    builder_.build(view, batches, batchCount, settings.options.techniqueOverride, techniquesDrawnBy(DrawnBy::Mega),
                   &record->list, config_.jobs);
    const int drawn = record->list.particleCount();
    if (drawn == 0) return 0;  // no Mega batch visible: nothing declared, nothing loaded
    if (!ensureLoaded()) return 0;

    record->view = view;
    record->view.name = "";  // the host's string is not ours to keep
    const ParticleBatch& first = batches[record->list.batches.front().rampRow];
    record->mega = first.desc->mega;
    record->lighting = first.desc->lighting;
    record->light = settings.light;
    record->softScale = record->list.batches.front().softScale;
    record->time = first.time;
    record->rect = screenRect(view, record->list.instances.data(), drawn);
    if (!record->rect.whole && record->rect.x1 <= record->rect.x0) return 0;  // nothing in front

    passes_.ramp().setRows(batches, batchCount);

    const float scale = std::clamp(record->mega.resolution, 0.25f, 1.0f);
    const Target sceneColor = frame.sceneColor();
    // The z-buffer, sampled in place, where the host offers it; else its linear depth.
    const SceneDepthSource source = sceneDepthSource(frame, view);
    const Target sceneDepth = source.target;
    record->depthDecode = source.decode;
    const Target megaDepth = frame.createTarget("mega_depth", megaTarget(scale, TargetFormat::R32F));
    const Target color = frame.createTarget("mega_color", megaTarget(scale, TargetFormat::RGBA16F));
    const Target density = frame.createTarget("mega_density", megaTarget(scale, TargetFormat::RGBA16F));
    const Target blurColor = frame.createTarget("mega_blur_color", megaTarget(scale, TargetFormat::RGBA16F));
    const Target blurDensity = frame.createTarget("mega_blur_density", megaTarget(scale, TargetFormat::RGBA16F));
    const Target cloud = frame.createTarget("mega_cloud", megaTarget(scale, TargetFormat::RGBA16F));
    const Target cloudDepth = frame.createTarget("mega_cloud_depth", megaTarget(scale, TargetFormat::R32F));

    frame.addPass(kDepthPass, {sceneDepth}, {megaDepth}, [this, record, sceneDepth, megaDepth](PassContext& ctx) {
        GlStateGuard guard;
        passes_.runDepth(ctx, *record, sceneDepth, megaDepth);
    });
    frame.addPass(kSpheresPass, {megaDepth}, {color, density},
                  [this, record, megaDepth, color, density](PassContext& ctx) {
                      GlStateGuard guard;
                      passes_.runSpheres(ctx, *record, megaDepth, color, density);
                  });
    frame.addPass(kBlurHPass, {color, density}, {blurColor, blurDensity},
                  [this, record, color, density, blurColor, blurDensity](PassContext& ctx) {
                      GlStateGuard guard;
                      passes_.runBlur(ctx, *record, color, density, blurColor, blurDensity, false);
                  });
    frame.addPass(kBlurVPass, {blurColor, blurDensity}, {cloud, cloudDepth},
                  [this, record, blurColor, blurDensity, cloud, cloudDepth](PassContext& ctx) {
                      GlStateGuard guard;
                      passes_.runBlur(ctx, *record, blurColor, blurDensity, cloud, cloudDepth, true);
                  });
    frame.addPass(kCompositePass, {cloud, cloudDepth, sceneDepth}, {sceneColor},
                  [this, record, cloud, cloudDepth, sceneDepth, sceneColor](PassContext& ctx) {
                      GlStateGuard guard;
                      passes_.runComposite(ctx, *record, cloud, cloudDepth, sceneDepth, sceneColor);
                  });
    return drawn;
}

}  // namespace fx
