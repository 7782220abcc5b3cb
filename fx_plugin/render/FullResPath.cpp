#include "FullResPath.h"

#include <utility>

#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "PassDeclaration.h"
#include "SceneDepthSource.h"

namespace fx {

FullResPath::FullResPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch)
    : draw_(draw), sizeMismatch_(std::move(sizeMismatch)) {}

void FullResPath::declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& record,
                          std::function<bool()> drawHere) {
    const ViewInfo& view = record->view;
    const Target color = frame.sceneColor();
    const Target opacity = record->opacity;
    // The z-buffer, sampled in place, where the host offers it; else its linear depth.
    const SceneDepthSource source = record->list.needsSceneDepth ? sceneDepthSource(frame, view) : SceneDepthSource{};
    const Target depth = source.target;
    const SceneDepthDecode decode = source.decode;
    ScreenRect bound;  // whole
    if (depth.valid() && dynamic_cast<ImmediateFrame*>(&frame)) {
        const BillboardReach reach = draw_.billboardReach(*record, false);
        bound = screenRect(view, record->list.instances.data(), record->list.particleCount(), nullptr,
                           footprintOf(record->list), Jobs(), &reach);
    }
    narrowDepthRead(frame, bound, view.width, view.height);
    addPassReading(frame, kPass, {depth, opacity}, color,
                   [this, record, depth, decode, color, opacity, drawHere = std::move(drawHere)](PassContext& ctx) {
                       if (drawHere && !drawHere()) return;
                       if (!targetsFitView(ctx, record->view, color, depth, sizeMismatch_)) return;
                       execute(ctx, *record, color, depth, decode, opacity);
                   });
}

void FullResPath::execute(PassContext& ctx, const ParticleView& view, Target color, Target depth,
                          const SceneDepthDecode& decode, Target opacity) {
    GlStateGuard guard(view.view.depth);  // z-tested against the host's z-buffer
    DebugGroup group(kPass);
    ctx.bindForDraw(color);
    DrawInputs in;
    in.clip = HostClip::current();
    const TextureRef depthRef = depth.valid() ? ctx.texture(depth, 0) : TextureRef{};
    in.sceneDepth = depthRef.name;
    in.depthDecode = decode.placedFor(depthRef, view.view, true);  // drawn into sceneColor
    in.opacity = opacity.valid() ? ctx.texture(opacity, 0).name : 0;
    draw_.draw(view, in);
}

}  // namespace fx
