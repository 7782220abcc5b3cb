#pragma once
// The rendering modes fxbench compares. Each is a set of run-time switches applied to one Game
// before RenderFrame, so every mode renders the same simulated frame without re-init.
#include <string>
#include <vector>

#include "fx/Plugin.h"

namespace cube {
class Game;
}

namespace fxbench {

/// One mode. Defaults: the bare engine (effects off).
struct Mode {
    const char* name = "nofx";
    const char* setup = "";            ///< Table 1's "Method" wording
    bool effects = false;              ///< false: no particle passes at all
    fx::Technique technique = fx::Technique::Hard;
    bool prepassEqual = false;
    bool quarterRes = false;
    /// The mode whose frames this mode's image error is measured against (itself for the
    /// full-resolution techniques: then error is between two renders of the same frame, which
    /// checks that rendering is deterministic and must be 0).
    const char* reference = "nofx";
    /// Billboards as trimmed polygons (the plugin's default) or full quads (`soft-quads`).
    fx::ParticleShape shape = fx::ParticleShape::Trimmed;
    /// Lit smoke (the game's sun through Plugin::setSceneLight) or unlit (clearSceneLight).
    bool lit = false;
    /// API 2's immediate path on the engine's own z-buffer (`soft-zbuffer`) instead of the frame
    /// graph's passes.
    bool hostZBuffer = false;
    /// The frame graph's passes on a linear R32F scene depth the opaque pass writes as a second
    /// render target (API 2.0's contract, `soft-linear`) instead of sampling the z-buffer.
    bool linearDepth = false;
    /// Quarter res in every view (RenderOptions::quarterResAlways) instead of only where it pays.
    bool quarterResAlways = false;
    /// The tiled compute path (RenderOptions::tiled, `hard+tiled`, `soft+tiled`,
    /// `spherical+tiled`): particles shaded per 16 px tile, one scene-depth read and one blend
    /// per pixel.
    bool tiled = false;
};

/// Every mode, in table order: nofx, hard, soft, soft-quads, soft+equal, soft+quarter,
/// soft+quarter-always, soft+equal+quarter,
/// hard+tiled and soft+tiled (against hard and soft: the raster picture up to rounding),
/// spherical, spherical-quads, spherical+quarter, spherical+tiled (against spherical: up to
/// rounding), hard-lit, soft-lit,
/// spherical-lit, mega (image error
/// against spherical: the same particles as exact spheres), mega-lit (against spherical-lit),
/// soft-zbuffer and spherical-zbuffer (the immediate path on the engine's z-buffer, against
/// soft and spherical), soft-linear and spherical-linear (the frame graph on a linear R32F depth
/// target instead of the z-buffer, against soft and spherical).
const std::vector<Mode>& allModes();
/// Null when `name` is not a mode.
const Mode* findMode(const std::string& name);
/// "nofx, hard, ..." for messages.
std::string modeNameList();
/// Parses "a,b,c": known, distinct names. False + message listing the valid ones otherwise (for
/// a removed mode, also why it went).
bool parseModeList(const std::string& text, std::vector<std::string>* out, std::string* error);

/// Sets the game's and the plugin's switches for `mode` (HUD text does not depend on them: the
/// harness runs with the HUD off). A switch of technique or quarter res is
/// followed by Plugin::prepareGl, as the engine does after a key or panel switch: the programs
/// the mode draws with are built here, never while a frame is declared.
void applyMode(cube::Game& game, const Mode& mode);

}  // namespace fxbench
