#pragma once
// Draws the stateless reactions (technique: stateless): their birth records go to the GPU once
// (only the ring slots written since the last upload), and vs_stateless_particles.glsl evaluates
// every particle from the reaction's clock; the CPU does no work per particle per frame.
//
// One pass per view, "particles_stateless", declared after the other particle passes when any
// stateless reaction may have a live particle (ring liveUntil() > clock: O(1) per reaction); it
// writes the view's colour with the hard technique's depth test (Standard: LEQUAL, ReversedZ:
// GEQUAL, no depth writes) and additive blending (order-independent: never sorted). Every GL
// call runs inside a GlStateGuard. The program (ProgramCache::Stateless, in Renderers' cache) is
// built by prepare() (Plugin::prepareGl, when a stateless reaction is loaded) or at the first
// draw; one that fails to build is reported once through the host's log and the pass draws
// nothing; the other techniques are unaffected. Live shader edits rebuild it with the other
// particle programs (Renderers::reload, one swap of the cache).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ProgramCache.h"
#include "ScreenTiles.h"
#include "ShaderLoader.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class ReactionRuntime;

class StatelessRenderer {
public:
    /// Builds and draws with the program of `programs` (Renderers' cache, which outlives this).
    StatelessRenderer(HostAdapter* host, ProgramCache& programs);
    ~StatelessRenderer();
    StatelessRenderer(const StatelessRenderer&) = delete;
    StatelessRenderer& operator=(const StatelessRenderer&) = delete;

    /// Declares this view's pass when a stateless reaction may have live particles. Returns the
    /// number of record slots it will draw (an upper bound of the live particles).
    int declarePasses(const ViewInfo& view, FrameBuilder& frame,
                      const std::vector<ReactionRuntime>& runtimes);

    /// Builds the program now (Plugin::prepareGl with a stateless reaction loaded); false with
    /// the build's "file:line: message" lines appended to `out` (logged once, as at a draw).
    /// Context current.
    bool prepare(Diagnostics* out);
    /// After a reload swapped the cache's programs: where something stateless was drawn or
    /// prepared, the pass takes the new build. Context current.
    void programsSwapped();

    static constexpr const char* kPass = "particles_stateless";

private:
    struct Gpu;
    struct Draw;
    void draw(const ViewInfo& view, const std::vector<Draw>& draws, const HostClip& clip);
    bool ensureProgram();
    /// Makes the cache's program the one drawn with, with its uniforms.
    void adopt(uint32_t program);

    HostAdapter* host_;
    ProgramCache& programs_;
    std::string error_;  ///< the failed build's message (prepare() hands it out)
    std::unique_ptr<Gpu> gpu_;
};

}  // namespace fx
