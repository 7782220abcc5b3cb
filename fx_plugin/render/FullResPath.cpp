#include "FullResPath.h"

#include <string>
#include <utility>
#include <vector>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "PassDeclaration.h"
#include "SceneDepthSource.h"

namespace fx {

FullResPath::FullResPath(ParticleDraw& draw, HostAdapter* host, SizeMismatchReport sizeMismatch)
    : draw_(draw), host_(host), sizeMismatch_(std::move(sizeMismatch)) {}

std::unique_ptr<FadeClassifier> FullResPath::adoptReload(std::unique_ptr<FadeClassifier> rebuilt) {
    if (classifier_) classifier_.swap(rebuilt);
    classifierFailed_ = false;
    return rebuilt;
}

bool FullResPath::ensureClassifier(const ShaderReader& sources, std::vector<std::string>* failures) {
    if (classifier_) return true;
    if (classifierFailed_) return false;
    GlStateGuard guard;
    auto classifier = std::make_unique<FadeClassifier>();
    std::vector<std::string> errors;
    classifier->build(sources, &errors);                                  // the files of the running programs
    draw_.programs().build(ProgramCache::classifiedKeys(), &errors);  // tried once per cache
    bool programsOk = true;
    for (const ProgramCache::Key& k : ProgramCache::classifiedKeys()) {
        programsOk = programsOk && (k.lit || draw_.programs().find(k));
    }
    if (!errors.empty() || !classifier->ok() || !programsOk) {
        std::string text = "fx: fade classification is off: its programs did not build";
        if (failures) {
            failures->insert(failures->end(), errors.begin(), errors.end());
        } else {
            for (const std::string& e : errors) text += "\n" + e;
        }
        if (host_) host_->log(LogLevel::Error, text.c_str());
        classifierFailed_ = true;
        return false;
    }
    classifier_ = std::move(classifier);
    return true;
}

void FullResPath::declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& record,
                          const ShaderReader& sources) {
    const ViewInfo& view = record->view;
    const Target color = frame.sceneColor();
    const Target opacity = record->opacity;
    // The z-buffer, sampled in place, where the host offers it; else its linear depth.
    const SceneDepthSource source = record->list.needsSceneDepth ? sceneDepthSource(frame, view) : SceneDepthSource{};
    const Target depth = source.target;
    const SceneDepthDecode decode = source.decode;
    ScreenRect bound;  // whole
    if (depth.valid() && dynamic_cast<ImmediateFrame*>(&frame)) {
        bound = screenRect(view, record->list.instances.data(), record->list.particleCount(), nullptr,
                           footprintOf(record->list));
    }
    // Fade classification: the scene depth's range per tile, read by the classified programs.
    Target tiles, coarse;
    if (record->settings.classify && depth.valid() && ensureClassifier(sources)) {
        tiles = frame.createTarget(FadeClassifier::kTileTarget,
                                   FadeClassifier::tileTargetDesc(view.width, view.height, false));
        coarse = frame.createTarget(FadeClassifier::kCoarseTarget,
                                    FadeClassifier::tileTargetDesc(view.width, view.height, true));
        narrowDepthRead(frame, bound, view.width, view.height);
        frame.addPass(FadeClassifier::kPass, {depth}, {tiles, coarse},
                      [this, record, depth, decode, tiles, coarse](PassContext& ctx) {
                          if (!targetsFitView(ctx, record->view, depth, Target{}, sizeMismatch_)) return;
                          GlStateGuard guard;
                          DebugGroup group(FadeClassifier::kPass);
                          classifier_->buildTiles(ctx, depth, decode.placedFor(ctx.texture(depth, 0), record->view, false),
                                                  tiles, coarse);
                      });
    }
    const bool count = tiles.valid() && record->settings.countClasses;
    narrowDepthRead(frame, bound, view.width, view.height);
    addPassReading(frame, kPass, {depth, opacity, tiles, coarse}, color,
                   [this, record, depth, decode, color, opacity, tiles, coarse, count](PassContext& ctx) {
                       if (!targetsFitView(ctx, record->view, color, depth, sizeMismatch_)) return;
                       GlStateGuard guard(record->view.depth);  // z-tested against the host's z-buffer
                       DebugGroup group(kPass);
                       ctx.bindForDraw(color);
                       DrawInputs in;
                       in.clip = HostClip::current();
                       const TextureRef depthRef = depth.valid() ? ctx.texture(depth, 0) : TextureRef{};
                       in.sceneDepth = depthRef.name;
                       in.depthDecode = decode.placedFor(depthRef, record->view, true);  // drawn into sceneColor
                       in.opacity = opacity.valid() ? ctx.texture(opacity, 0).name : 0;
                       in.tiles = tiles.valid() ? ctx.texture(tiles, 0).name : 0;
                       in.coarse = coarse.valid() ? ctx.texture(coarse, 0).name : 0;
                       draw_.draw(*record, in);
                       if (count) {
                           counts_ = classifier_->count(record->list.batches, draw_.stream(), record->view,
                                                        in.tiles, in.coarse);
                       }
                   });
}

}  // namespace fx
