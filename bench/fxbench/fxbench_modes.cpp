#include "fxbench_modes.h"

#include <algorithm>

#include "fxbench_named.h"
#include "game/Game.h"

namespace fxbench {

const std::vector<Mode>& allModes() {
    using fx::Technique;
    // name, setup, effects, technique, prepassEqual, quarterRes, reference[, shape, lit, hostZBuffer,
    // linearDepth, quarterResAlways, tiled]
    static const std::vector<Mode> modes = {
        {"nofx", "No particles (bare engine)", false, Technique::Hard, false, false, "nofx"},
        {"hard", "Hard particles", true, Technique::Hard, false, false, "hard"},
        {"soft", "Soft particles, no optimizations", true, Technique::Soft, false, false, "soft"},
        {"soft-quads", "Soft particles drawn as full quads (untrimmed)", true, Technique::Soft, false, false, "soft",
         fx::ParticleShape::Quad},
        {"soft+equal", "Soft particles, utilize prepass z-buffer (EQUAL)", true, Technique::Soft, true, false,
         "soft"},
        {"soft+quarter", "Soft particles, 1/4-size texture where it pays", true, Technique::Soft, false, true,
         "soft"},
        // Quarter res in every view, also where full res is cheaper (the 2.0 behaviour).
        {"soft+quarter-always", "Soft particles, 1/4-size texture in every view", true, Technique::Soft, false, true,
         "soft", fx::ParticleShape::Trimmed, false, false, false, true},
        {"soft+equal+quarter", "Soft particles, prepass EQUAL + 1/4-size texture", true, Technique::Soft, true,
         true, "soft"},
        // Shaded per 16 px tile by a compute shader (TiledPath.h): one depth read and one blend per pixel.
        {"hard+tiled", "Hard particles, shaded per screen tile (compute)", true, Technique::Hard, false, false, "hard",
         fx::ParticleShape::Trimmed, false, false, false, false, true},
        {"soft+tiled", "Soft particles, shaded per screen tile (compute)", true, Technique::Soft, false, false, "soft",
         fx::ParticleShape::Trimmed, false, false, false, false, true},
        {"spherical", "Spherical billboards", true, Technique::Spherical, false, false, "spherical"},
        {"spherical-quads", "Spherical billboards drawn as full quads (untrimmed)", true, Technique::Spherical, false,
         false, "spherical", fx::ParticleShape::Quad},
        {"spherical+quarter", "Spherical billboards, 1/4-size texture", true, Technique::Spherical, false, true,
         "spherical"},
        {"spherical+tiled", "Spherical billboards, shaded per screen tile (compute)", true, Technique::Spherical,
         false, false, "spherical", fx::ParticleShape::Trimmed, false, false, false, false, true},
        // Lit smoke: normals, sun, scattering and the opacity map; each its own
        // reference (the cost of light is read against the unlit row above it).
        {"hard-lit", "Hard particles, lit and self-shadowed", true, Technique::Hard, false, false, "hard-lit",
         fx::ParticleShape::Trimmed, true},
        {"soft-lit", "Soft particles, lit and self-shadowed", true, Technique::Soft, false, false, "soft-lit",
         fx::ParticleShape::Trimmed, true},
        {"spherical-lit", "Spherical billboards, lit and self-shadowed", true, Technique::Spherical, false, false,
         "spherical-lit", fx::ParticleShape::Trimmed, true},
        // Lit smoke shaded per tile: the light per corner (sphere: centre) as the raster vertex
        // shader works it out, read across the quad's triangles (cs_particles_tiled.glsl).
        {"soft-lit+tiled", "Soft particles, lit and self-shadowed, shaded per screen tile (compute)", true,
         Technique::Soft, false, false, "soft-lit", fx::ParticleShape::Trimmed, true, false, false, false, true},
        {"spherical-lit+tiled", "Spherical billboards, lit and self-shadowed, shaded per screen tile (compute)", true,
         Technique::Spherical, false, false, "spherical-lit", fx::ParticleShape::Trimmed, true, false, false, false,
         true},
        // Mega-particles (seed 001): the same particles as blurred, lit spheres melted into one
        // volume. Its image error is measured against `spherical`, the same particles drawn as
        // exact spheres: it says how far the blur, the noise and the reduced resolution move the
        // picture from the exact volumes (not a bug figure: the look differs on purpose).
        {"mega", "Mega-particles (blurred spheres as one volume)", true, Technique::Mega, false, false, "spherical"},
        {"mega-lit", "Mega-particles, lit", true, Technique::Mega, false, false, "spherical-lit",
         fx::ParticleShape::Trimmed, true},
        // The plugin's immediate path (renderView) on the engine's z-buffer: one copy of it,
        // decoded in the particle shaders, instead of the frame graph's passes.
        {"soft-zbuffer", "Soft particles, host z-buffer through the immediate path", true, Technique::Soft, false,
         false, "soft", fx::ParticleShape::Trimmed, false, true},
        {"spherical-zbuffer", "Spherical billboards, host z-buffer through the immediate path", true,
         Technique::Spherical, false, false, "spherical", fx::ParticleShape::Trimmed, false, true},
        // API 2.0's depth contract: the opaque pass writes linear R32F depth as a second render
        // target for the particles to read, instead of their sampling the z-buffer it drew. The
        // same picture within 1/255; the difference in cost is that second target.
        {"soft-linear", "Soft particles, linear depth as a second render target", true, Technique::Soft, false,
         false, "soft", fx::ParticleShape::Trimmed, false, false, true},
        {"spherical-linear", "Spherical billboards, linear depth as a second render target", true,
         Technique::Spherical, false, false, "spherical", fx::ParticleShape::Trimmed, false, false, true},
    };
    return modes;
}

const Mode* findMode(const std::string& name) { return findNamed(allModes(), name); }

std::string modeNameList() { return namedList(allModes()); }

namespace {

// Modes of earlier builds whose rendering feature was removed: named in the refusal so a script
// written for them learns why rather than only that the name is unknown.
const char* removedModeReason(const std::string& name) {
    if (name == "soft+classify" || name == "spherical+classify") {
        return "fade classification was removed in API 2.4 (on an H200 its depth pyramid and masks made the "
               "particle pass 1.27x longer than without); soft+tiled and spherical+tiled read the depth once per "
               "pixel";
    }
    if (name == "soft+mixed") {
        return "mixed resolution was removed in API 2.1 (on a GPU its edge pass cost more than quarter res "
               "saves, for no better image)";
    }
    return nullptr;
}

}  // namespace

bool parseModeList(const std::string& text, std::vector<std::string>* out, std::string* error) {
    out->clear();
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (!findMode(name)) {
            const char* removed = removedModeReason(name);
            *error = removed ? "--modes: mode '" + name + "' no longer exists: " + removed + "; valid modes: " +
                                   modeNameList()
                             : "--modes: unknown mode '" + name + "'; valid modes: " + modeNameList();
            return false;
        }
        if (std::find(out->begin(), out->end(), name) != out->end()) {
            *error = "--modes: mode '" + name + "' given twice";
            return false;
        }
        out->push_back(name);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return true;
}

void applyMode(cube::Game& game, const Mode& mode) {
    game.options().effects = mode.effects;
    game.options().prepassEqual = mode.prepassEqual;
    game.options().pluginZBuffer = mode.hostZBuffer;
    game.options().pluginLinearDepth = mode.linearDepth;
    fx::Plugin* plugin = game.specialFX().plugin();
    if (!plugin) return;
    const fx::RenderOptions was = plugin->renderOptions();
    fx::RenderOptions ro = was;
    ro.techniqueOverride = mode.technique;
    ro.quarterRes = mode.quarterRes;
    ro.quarterResAlways = mode.quarterResAlways;
    ro.bilinearUpsample = false;  // the depth-aware composite is the one under test
    // Each mode names its path: a +tiled mode tiled on any context, the others rasterised (also
    // on a GPU, where the default, Tiling::Auto, would draw them tiled).
    ro.tiled = false;
    ro.tiling = mode.tiled ? fx::Tiling::On : fx::Tiling::Off;
    plugin->setRenderOptions(ro);
    plugin->setParticleShape(mode.shape);
    // The engine's rule for a window key or a panel switch (Render::handleKeys, the panel): a
    // switch that may reach programs the old one did not is followed by prepareGl, between
    // frames, so no program is built while the next frame is declared (nor inside a timed render).
    if (ro.techniqueOverride != was.techniqueOverride || ro.quarterRes != was.quarterRes ||
        ro.quarterResAlways != was.quarterResAlways || ro.bilinearUpsample != was.bilinearUpsample ||
        ro.tiled != was.tiled || ro.tiling != was.tiling) {
        (void)plugin->prepareGl(nullptr);  // a failure is logged once by the plugin
    }
    if (mode.lit) {
        game.specialFX().setSceneLight(game.sun());
    } else {
        plugin->clearSceneLight();
    }
}

}  // namespace fxbench
