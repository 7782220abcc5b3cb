#pragma once
// Full resolution (the default path): the billboard particles drawn straight into sceneColor.
//   "particles"  reads sceneDepth only if a visible batch is soft or spherical (and the opacity
//                map for lit smoke), writes sceneColor
// Depth testing as ParticleRenderer.h says: hard particles always test the host's z-buffer, soft
// and spherical ones under reversed-Z; all of them without writing it.
#include <functional>
#include <memory>

#include "ParticleDraw.h"
#include "RendererConfig.h"

namespace fx {

class FullResPath {
public:
    static constexpr const char* kPass = "particles";

    FullResPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch);
    FullResPath(const FullResPath&) = delete;
    FullResPath& operator=(const FullResPath&) = delete;

    /// Declares the view's pass; with `drawHere`, the pass draws only where that returns true
    /// when it runs (a choice that waits for the passes: ParticleView::quarter).
    void declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& view,
                 std::function<bool()> drawHere = nullptr);
    /// What the declared pass runs: the view drawn into `color` (inside its own guard), reading
    /// `depth` (decoded by `decode`) and lit smoke's `opacity` where valid. Also the tiled path's
    /// fallback (TiledPath::declare), in a pass that declared the same reads and write.
    void execute(PassContext& ctx, const ParticleView& view, Target color, Target depth,
                 const SceneDepthDecode& decode, Target opacity);

private:
    ParticleDraw& draw_;
    SizeMismatchReport sizeMismatch_;
};

}  // namespace fx
