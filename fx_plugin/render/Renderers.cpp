#include "Renderers.h"

#include <algorithm>

#include "GlStateGuard.h"
#include "ProgramCache.h"
#include "ShaderLoader.h"
#include "ViewCheck.h"
#include "base/ApiErrors.h"
#include "reactions/TechniqueTable.h"
#include "sim/ReactionRuntime.h"

namespace fx {

Renderers::Renderers(const RendererConfig& config)
    : config_(config),
      programs_(snapshotShaderReader(shaderReader(config.shaderDir))),
      billboards_(config, programs_),
      mega_(config, programs_),
      stateless_(config.host, programs_),
      immediate_(config.host, programs_) {
    immediate_.setApiErrors(config.errors);
}

Renderers::~Renderers() {
    if (programs_.empty()) return;  // nothing built: no GL to touch
    GlStateGuard guard;
    ProgramCache none;
    programs_.swap(none);  // every program deleted with `none`, inside the guard
}

void Renderers::collectBatches(const std::vector<ReactionRuntime>& runtimes) {
    batches_.clear();
    for (const ReactionRuntime& r : runtimes) {
        batches_.push_back(ParticleBatch{&r.pool(), &r.desc(), r.needsSorting(), float(r.time())});
    }
}

bool Renderers::prepare(const std::vector<ReactionRuntime>& runtimes, const FrameSettings& settings,
                        Diagnostics* out) {
    const Technique override = settings.options.techniqueOverride;
    bool mega = false, stateless = false;
    auto wants = [&](const TechniqueRow& row) {
        mega = mega || row.drawnBy == DrawnBy::Mega;
        stateless = stateless || row.drawnBy == DrawnBy::Stateless;
    };
    // The override's renderer (mega with no mega reaction loaded), and each reaction's own even
    // under an override, so that switching the override back draws without a build.
    if (override != Technique::FromReaction) wants(techniqueRow(override, false));
    std::vector<int> powerSteps;  // 2 contrast_power of each power program the reactions draw with
    for (const ReactionRuntime& r : runtimes) {
        wants(techniqueRow(r.desc().render.technique, r.stateless()));
        const TechniqueRow& row = drawnRow(r.desc().render.technique, r.stateless(), override);
        int whole = 0, half = 0;
        if (!row.powerPrograms || !ProgramCache::halfWholePower(r.desc().render.contrastPower, &whole, &half)) continue;
        const int s = 2 * whole + half;
        if (std::find(powerSteps.begin(), powerSteps.end(), s) == powerSteps.end()) powerSteps.push_back(s);
    }
    bool ok = billboards_.prepare(out, powerSteps, settings.options.quarterRes, TiledPath::wanted(settings.options));
    if (mega) ok = mega_.prepare(out) && ok;
    if (stateless) ok = stateless_.prepare(out) && ok;
    // The immediate path's own program too: the first renderView then compiles nothing.
    return immediate_.prepare(out) && ok;
}

ErrorCode Renderers::declare(const ViewInfo& view, FrameBuilder& frame, const std::vector<ReactionRuntime>& runtimes,
                             const FrameSettings& settings, int* drawn) {
    const std::string bad = viewProblem(view);
    if (!bad.empty()) {
        *drawn = 0;
        return config_.errors ? config_.errors->refuse(ErrorCode::InvalidView, "declarePasses", bad) : ErrorCode::InvalidView;
    }
    FrameScope declaring(FrameScope::Declare);
    collectBatches(runtimes);
    const int count = static_cast<int>(batches_.size());
    // Each batch is drawn by one renderer: each builds its list from the techniques it draws.
    *drawn = billboards_.declarePasses(view, frame, batches_.data(), count, settings) +
             mega_.declarePasses(view, frame, batches_.data(), count, settings) +
             stateless_.declarePasses(view, frame, runtimes);
    return ErrorCode::None;
}

SmokeShadow Renderers::declareShadow(const ViewInfo& view, FrameBuilder& frame,
                                     const std::vector<ReactionRuntime>& runtimes, const FrameSettings& settings) {
    if (!settings.light.on) return SmokeShadow{};
    FrameScope declaring(FrameScope::Declare);
    collectBatches(runtimes);
    return billboards_.declareShadowPasses(view, frame, batches_.data(), static_cast<int>(batches_.size()),
                                           settings.light);
}

bool Renderers::reload(Diagnostics* out) {
    if (!billboards_.shadersChanged()) return false;
    GlStateGuard guard;
    // Every technique's programs in one transaction: all go live or none, and one edit gives one
    // line, whichever technique's file it broke. A new cache is built from the folder's current
    // files: every key the running cache tried (nothing is missing after the swap), and the mega
    // and stateless programs even when not in use, so a broken file of theirs is reported at the
    // edit rather than when a reaction first asks for them.
    ShaderErrorLog errors;
    ProgramCache staged(snapshotShaderReader(shaderReader(config_.shaderDir)));
    std::vector<ProgramCache::Key> keys = programs_.keys();
    for (const ProgramCache::Key& k : ProgramCache::megaKeys()) keys.push_back(k);
    keys.push_back(ProgramCache::Key::of(ProgramCache::Stateless));
    std::vector<std::string> failed;
    staged.build(keys, &failed);  // a key listed twice is built once
    for (const std::string& e : failed) errors.add(e);
    if (!errors.empty()) {
        // The staged programs are deleted (`staged` at the end of this scope, inside the guard);
        // the running ones stay, so the smoke on screen does not change.
        logTo(config_, LogLevel::Error, "fx: particle shaders in " + config_.shaderDir +
                                            " changed but do not build; the last good programs are kept:\n" +
                                            errors.text());
        if (out) addShaderDiagnostics(errors.text(), out);
        return false;
    }
    programs_.swap(staged);  // the old programs are deleted with `staged`, inside the guard
    billboards_.programsSwapped();
    mega_.programsSwapped();
    stateless_.programsSwapped();
    logTo(config_, LogLevel::Info, "fx: particle shaders reloaded from " + config_.shaderDir);
    return true;
}

}  // namespace fx
