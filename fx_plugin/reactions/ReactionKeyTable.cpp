#include "ReactionKeyTable.h"

#include <charconv>

#include "reactions/TechniqueTable.h"

namespace fx {
namespace {

using Kind = ReactionKeyInfo::Kind;

ReactionKeyInfo key(const char* path, Kind kind, double lo, double hi, const char* unit,
                    const char* help, std::vector<std::string> choices = {}) {
    return {path, kind, lo, hi, std::move(choices), unit, help};
}

// "hard sprites, soft particles (depth fade), ... or mega-particles (...)": the table's names.
std::string techniqueHelp() {
    std::string help;
    const std::vector<TechniqueRow>& rows = techniqueTable();
    for (size_t i = 0; i < rows.size(); ++i) {
        help += (i == 0 ? "" : i + 1 == rows.size() ? " or " : ", ") + std::string(rows[i].displayName);
    }
    return help;
}

std::vector<ReactionKeyInfo> buildTable() {
    // Enum words: ReactionNames.cpp and TechniqueTable.cpp, the lists the loader parses with.
    const std::vector<std::string>& surfaces = surfaceWords();
    const std::string techniques = techniqueHelp();
    // Ranges: the literals of ReactionSchema.cpp; meanings: reactions/README.md.
    return {
        key("name", Kind::Name, 1, 64, "", "unique name; a reaction keeps its live particles across a reload when its name and capacity stay the same"),
        key("type", Kind::Choice, 0, 0, "", "what drives it: wheel slip (wheel_smoke), speed on loose ground (dust) or a collision (collision_burst)",
            reactionTypeWords()),
        key("trigger.slip_threshold", Kind::Number, 0.0, 1.0, "slip fraction", "combined wheel slip at which emission starts"),
        key("trigger.surfaces", Kind::ChoiceList, 1, 8, "", "ground under the wheel that emits", surfaces),
        key("trigger.wheels", Kind::Choice, 0, 0, "", "which wheels emit", wheelSetWords()),
        key("trigger.min_speed", Kind::Number, 0.0, 200.0, "m/s", "hub speed below which a wheel emits nothing"),
        key("trigger.collision_threshold", Kind::Number, 0.0, 1.0, "collision amount", "collision_burst only: amount that fires a burst"),
        key("emission.rate", Kind::Number, 0.0, 100000.0, "particles/s per wheel", "emission at full strength (wheel_smoke, dust)"),
        key("emission.burst", Kind::Integer, 0, kMaxCapacity, "particles", "collision_burst: particles per hit at collision amount 1; burst <= capacity"),
        key("emission.capacity", Kind::Integer, 1, kMaxCapacity, "particles", "pool size, allocated once at load; emission beyond it is dropped (changing it restarts the reaction's particles)"),
        key("emission.spawn_height", Kind::Number, -10.0, 10.0, "m", "spawn point above the wheel contact / collision point"),
        key("emission.jitter_radius", Kind::Number, 0.0, 10.0, "m", "spawn points are uniform in a horizontal disc of this radius"),
        key("particle.lifetime", Kind::NumberRange, 0.01, 60.0, "s", "each particle's life, uniform in [min, max]; min <= max"),
        key("particle.start_size", Kind::Number, 0.0, 10000.0, "m", "billboard edge length at birth"),
        key("particle.end_size", Kind::Number, 0.0, 10000.0, "m", "edge length at death"),
        key("particle.size_variation", Kind::Number, 0.0, 0.9, "fraction", "each particle's sizes are scaled by 1 +- up to this"),
        key("particle.rise_speed", Kind::Number, -50.0, 50.0, "m/s", "terminal upward speed (buoyancy); negative sinks"),
        key("particle.drag", Kind::Number, 0.0, 1.0e6, "1/s", "rate k at which velocity relaxes to its terminal value (halves every 0.69/k s)"),
        key("particle.wind_factor", Kind::Number, 0.0, 10.0, "", "share of the ambient wind in the terminal velocity"),
        key("particle.spread_speed", Kind::Number, 0.0, 100.0, "m/s", "random initial speed, random direction in the upper hemisphere"),
        key("particle.inherit_velocity", Kind::Number, 0.0, 2.0, "", "share of the wheel hub's velocity at birth"),
        key("particle.spin", Kind::NumberRange, -50.0, 50.0, "rad/s", "rotation speed of the billboard, uniform in [min, max]; min <= max"),
        key("particle.fade_in", Kind::Number, 0.0, 1.0, "life fraction", "alpha rises 0 -> 1 over this first part of life; fade_in + fade_out <= 1"),
        key("particle.fade_out", Kind::Number, 0.0, 1.0, "life fraction", "alpha falls 1 -> 0 over this last part of life; fade_in + fade_out <= 1"),
        key("particle.colour_ramp", Kind::ColorRamp, 1, kMaxColorStops, "",
            "colour over life, piecewise linear; t in [0, 1] non-decreasing, rgba each in [0, 1], straight alpha; two stops with one t make a hard step"),
        key("particle.atlas", Kind::IntegerPair, 0, 4, "frames",
            "[first, count] frames of the 2x2 smoke atlas picked at random per particle: first in [0, 3], count in [1, 4], first + count <= 4"),
        key("render.technique", Kind::Choice, 0, 0, "", techniques.c_str(), techniqueWords()),
        key("render.blend", Kind::Choice, 0, 0, "", "how particles combine with what is behind them; additive is order-independent",
            blendModeWords()),
        key("render.softness", Kind::Number, 1.0e-6, 1.0e6, "m", "depth difference over which the soft fade reaches 1 (the shader's scale is 1/softness)"),
        key("render.contrast_power", Kind::Number, 0.1, 16.0, "", "exponent of the soft-fade contrast curve; 1 = linear"),
        key("render.near_fade", Kind::Number, 0.0, 100.0, "m", "distance in front of the near plane over which particles fade out"),
        key("render.sort_back_to_front", Kind::Bool, 0, 0, "", "sort particles far to near each frame; never done for additive"),
        key("lighting.enabled", Kind::Bool, 0, 0, "", "lit by the host's sun and ambient when it gives them; additive reactions are never lit"),
        key("lighting.normal_strength", Kind::Number, 0.0, 1.0, "", "share of the atlas normals against a flat card facing the camera"),
        key("lighting.scattering", Kind::Number, 0.0, 1.0, "", "share of the sun light scattered by the Henyey-Greenstein phase (glowing edges against the sun)"),
        key("lighting.anisotropy", Kind::Number, -0.95, 0.95, "", "Henyey-Greenstein g: > 0 scatters forward (bright toward the sun), 0 evenly"),
        key("lighting.absorption", Kind::Number, 0.0, 20.0, "", "optical depth per unit of smoke opacity between a particle and the sun (self-shadowing strength)"),
        key("lighting.ambient", Kind::Number, 0.0, 2.0, "", "multiplier of the host's ambient light"),
        key("lighting.casts_shadow", Kind::Bool, 0, 0, "", "drawn into the opacity map: shadows other smoke and the ground"),
        key("mega.resolution", Kind::Number, 0.25, 1.0, "", "technique mega: size of the sphere target relative to the view"),
        key("mega.blur_radius", Kind::Number, 0.0, 32.0, "px", "technique mega: blur radius in pixels of the sphere target"),
        key("mega.noise_strength", Kind::Number, 0.0, 1.0, "", "technique mega: how much fractal noise eats into the cloud's alpha"),
        key("mega.noise_scale", Kind::Number, 0.05, 100.0, "m", "technique mega: size of the largest fractal noise feature"),
    };
}

std::string num(float v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string pair(const std::string& a, const std::string& b) { return "[" + a + ", " + b + "]"; }

}  // namespace

const std::vector<ReactionKeyInfo>& reactionKeyTable() {
    static const std::vector<ReactionKeyInfo> table = buildTable();
    return table;
}

std::string reactionValueText(const ReactionDesc& d, const std::string& k) {
    const TriggerDesc& t = d.trigger;
    const EmissionDesc& e = d.emission;
    const ParticleDesc& p = d.particle;
    const RenderDesc& r = d.render;
    if (k == "name") return d.name;
    if (k == "type") return reactionTypeName(d.type);
    if (k == "trigger.slip_threshold") return num(t.slipThreshold);
    if (k == "trigger.surfaces") {
        std::string s;
        for (int i = 0; i < int(Surface::Count); ++i) {
            if (t.surfaces & surfaceBit(Surface(i))) s += (s.empty() ? "" : ", ") + std::string(surfaceName(Surface(i)));
        }
        return "[" + s + "]";
    }
    if (k == "trigger.wheels") return wheelSetName(t.wheels);
    if (k == "trigger.min_speed") return num(t.minSpeed);
    if (k == "trigger.collision_threshold") return num(t.collisionThreshold);
    if (k == "emission.rate") return num(e.rate);
    if (k == "emission.burst") return std::to_string(e.burst);
    if (k == "emission.capacity") return std::to_string(e.capacity);
    if (k == "emission.spawn_height") return num(e.spawnHeight);
    if (k == "emission.jitter_radius") return num(e.jitterRadius);
    if (k == "particle.lifetime") return pair(num(p.lifetimeMin), num(p.lifetimeMax));
    if (k == "particle.start_size") return num(p.startSize);
    if (k == "particle.end_size") return num(p.endSize);
    if (k == "particle.size_variation") return num(p.sizeVariation);
    if (k == "particle.rise_speed") return num(p.riseSpeed);
    if (k == "particle.drag") return num(p.drag);
    if (k == "particle.wind_factor") return num(p.windFactor);
    if (k == "particle.spread_speed") return num(p.spreadSpeed);
    if (k == "particle.inherit_velocity") return num(p.inheritVelocity);
    if (k == "particle.spin") return pair(num(p.spinMin), num(p.spinMax));
    if (k == "particle.fade_in") return num(p.fadeIn);
    if (k == "particle.fade_out") return num(p.fadeOut);
    if (k == "particle.colour_ramp") {
        std::string s;
        for (const ColorStop& c : p.colorRamp) {
            s += (s.empty() ? "{t: " : ", {t: ") + num(c.t) + ", rgba: [" + num(c.rgba.r) + ", " + num(c.rgba.g) +
                 ", " + num(c.rgba.b) + ", " + num(c.rgba.a) + "]}";
        }
        return "[" + s + "]";
    }
    if (k == "particle.atlas") return pair(std::to_string(p.atlasFirst), std::to_string(p.atlasCount));
    if (k == "render.technique") return techniqueRow(r.technique, r.stateless).word;
    if (k == "render.blend") return blendModeName(r.blend);
    if (k == "render.softness") return num(r.softness);
    if (k == "render.contrast_power") return num(r.contrastPower);
    if (k == "render.near_fade") return num(r.nearFade);
    if (k == "render.sort_back_to_front") return r.sortBackToFront ? "true" : "false";
    const LightingDesc& l = d.lighting;
    if (k == "lighting.enabled") return l.enabled ? "true" : "false";
    if (k == "lighting.normal_strength") return num(l.normalStrength);
    if (k == "lighting.scattering") return num(l.scattering);
    if (k == "lighting.anisotropy") return num(l.anisotropy);
    if (k == "lighting.absorption") return num(l.absorption);
    if (k == "lighting.ambient") return num(l.ambient);
    if (k == "lighting.casts_shadow") return l.castsShadow ? "true" : "false";
    if (k == "mega.resolution") return num(d.mega.resolution);
    if (k == "mega.blur_radius") return num(d.mega.blurRadius);
    if (k == "mega.noise_strength") return num(d.mega.noiseStrength);
    if (k == "mega.noise_scale") return num(d.mega.noiseScale);
    return std::string();
}

}  // namespace fx
