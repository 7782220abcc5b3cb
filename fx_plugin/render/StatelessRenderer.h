#pragma once
// Draws the stateless reactions (technique: stateless): their birth records go to the GPU once
// (only the ring slots written since the last upload), and vs_stateless_particles.glsl evaluates
// every particle from the reaction's clock; the CPU does no work per particle per frame.
//
// One pass per view, "particles_stateless", declared after the other particle passes when any
// stateless reaction may have a live particle (ring liveUntil() > clock: O(1) per reaction); it
// writes the view's colour with the hard technique's depth test (Standard: LEQUAL, ReversedZ:
// GEQUAL, no depth writes) and additive blending (order-independent: never sorted). Every GL
// call runs inside a GlStateGuard. The program is built by prepare() (Plugin::prepareGl, when a
// stateless reaction is loaded) or at the first draw; one that fails to build is reported once
// through the host's log and the pass draws nothing; the other techniques are unaffected. Live
// shader edits rebuild it with the other particle programs (stageShaders, Renderers::reload).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ScreenTiles.h"
#include "ShaderLoader.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class ReactionRuntime;

class StatelessRenderer {
public:
    StatelessRenderer(HostAdapter* host, std::string shaderDir);
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
    /// A shader reload's stateless part (Renderers::reload): builds the program from the
    /// folder's current files and adds a failure to `errors`; it is staged only when it built and
    /// something stateless was drawn or prepared (else the build only checked the files).
    /// commitShaders makes it live, dropShaders deletes it. Context current.
    void stageShaders(ShaderErrorLog* errors);
    void commitShaders();
    void dropShaders();

    static constexpr const char* kPass = "particles_stateless";

private:
    struct Gpu;
    struct Draw;
    void draw(const ViewInfo& view, const std::vector<Draw>& draws, const HostClip& clip);
    bool ensureProgram();
    /// Makes `program` the one drawn with (deleting the previous one), with its uniforms.
    void adopt(uint32_t program);

    HostAdapter* host_;
    std::string shaderDir_;
    std::string error_;  ///< the failed build's message (prepare() hands it out)
    std::unique_ptr<Gpu> gpu_;
    uint32_t staged_ = 0;  ///< a reload's program until commitShaders
};

}  // namespace fx
