#pragma once
// The plugin's renderers under one owner: the billboards (ParticleRenderer), the mega-particles
// (MegaRenderer), the stateless reactions (StatelessRenderer) and the immediate path
// (ImmediateRenderer). PluginImpl holds one and calls it directly; nothing here reads a switch
// of the plugin's: every call is handed the running reactions and the frame's FrameSettings.
//
// Which renderer draws a reaction, and what each must build ahead, is the technique table's
// (reactions/TechniqueTable.h: TechniqueRow::drawnBy, powerPrograms); nothing here restates it.
//
// Order of one view's passes (names are data, see each renderer): the billboards' passes, then
// mega's, then "particles_stateless".
//
// Programs: one ProgramCache, owned here, holds the billboards', the quarter-res passes', the
// opacity map's, the immediate path's lineariser's (ProgramCache.h: one key type, one build
// function), and the mega and stateless renderers'. Only prepare (and the lazy builds of a host
// that skips prepareGl, before any pass) and reload compile into it; the renderers look their
// uniforms up on the programs it gives them.
//
// GL: every call but the constructor needs the host's context current once anything was loaded;
// destroy this with the context current (the renderers and the cache delete their GL objects).
#include <vector>

#include "DrawList.h"
#include "FrameSettings.h"
#include "ImmediateRenderer.h"
#include "MegaRenderer.h"
#include "ParticleRenderer.h"
#include "ProgramCache.h"
#include "RendererConfig.h"
#include "StatelessRenderer.h"
#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"

namespace fx {

class ReactionRuntime;

class Renderers {
public:
    /// `config.errors` counts the refusals (InvalidView, SizeMismatch, the immediate path's).
    explicit Renderers(const RendererConfig& config);
    ~Renderers();
    Renderers(const Renderers&) = delete;
    Renderers& operator=(const Renderers&) = delete;

    /// Plugin::prepareGl: every program `runtimes` can draw with under `settings` (a broken
    /// shader of any technique is reported now, each technique's failures once), and the
    /// immediate path's. True when everything built; else false with the problems in `out`.
    bool prepare(const std::vector<ReactionRuntime>& runtimes, const FrameSettings& settings, Diagnostics* out);

    /// Plugin::declarePasses: refuses an invalid view (InvalidView, `*drawn` 0); else declares
    /// the view's passes of every renderer and sets `*drawn` to the particles they draw.
    ErrorCode declare(const ViewInfo& view, FrameBuilder& frame, const std::vector<ReactionRuntime>& runtimes,
                      const FrameSettings& settings, int* drawn);

    /// Plugin::declareShadowPasses for a valid view: the opacity map's pass under
    /// `settings.light` (nothing when it is off).
    SmokeShadow declareShadow(const ViewInfo& view, FrameBuilder& frame, const std::vector<ReactionRuntime>& runtimes,
                              const FrameSettings& settings);

    /// Plugin::pollShaderReload, with Config::shaderDir set and the billboards loaded: when a
    /// plugin shader file there changed since the running programs were built, every renderer
    /// builds its programs anew; all build -> they all go live (true); any fails -> every running
    /// program stays, the failure is logged once for this edit (each distinct line once) and
    /// appended to `out`, false.
    bool reload(Diagnostics* out);

    /// The plugin, before any reaction's particles change: ParticleRenderer::settleLists.
    void settleLists() { billboards_.settleLists(); }

    /// The immediate path (Plugin::renderView): its render() declares through declare().
    ImmediateRenderer& immediate() { return immediate_; }
    const ParticleRenderer& billboards() const { return billboards_; }

private:
    /// The batches of `runtimes`, in `batches_` (its capacity kept across views).
    void collectBatches(const std::vector<ReactionRuntime>& runtimes);

    RendererConfig config_;
    // Built from one snapshot of the shader files (a reload swaps in a cache of a new one); the
    // renderers below hold it, so it is declared first.
    ProgramCache programs_;
    ParticleRenderer billboards_;
    MegaRenderer mega_;
    StatelessRenderer stateless_;
    ImmediateRenderer immediate_;
    std::vector<ParticleBatch> batches_;
};

}  // namespace fx
