#include "ReactionSchema.h"

#include <string>

#include "reactions/OptionalFields.h"
#include "reactions/TechniqueTable.h"

namespace fx {
namespace {

using YAML::Node;
using namespace schema;

void readTrigger(YamlCheck& c, const Node& node, const std::string& path, TriggerDesc* t) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path,
                {"slip_threshold", "surfaces", "wheels", "min_speed", "collision_threshold"});
    optNumber(c, m, "slip_threshold", 0.0, 1.0, &t->slipThreshold);
    optNumber(c, m, "min_speed", 0.0, 200.0, &t->minSpeed);
    optNumber(c, m, "collision_threshold", 0.0, 1.0, &t->collisionThreshold);
    optChoice(c, m, "wheels", wheelSetWords(), WheelSet::Rear, &t->wheels);
    if (const Node* n = m.get("surfaces")) {
        const std::string p = m.path("surfaces");
        if (c.isList(*n, p, 1, 8)) {
            uint32_t mask = 0;
            bool ok = true;
            size_t i = 0;
            for (auto it = n->begin(); it != n->end(); ++it, ++i) {
                int s = 0;
                if (c.choice(*it, indexed(p, i), surfaceWords(), &s)) {
                    mask |= surfaceBit(static_cast<Surface>(s));
                } else {
                    ok = false;
                }
            }
            if (ok) t->surfaces = mask;
        }
    }
}

void readEmission(YamlCheck& c, const Node& node, const std::string& path, EmissionDesc* e) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"rate", "burst", "capacity", "spawn_height", "jitter_radius"});
    optNumber(c, m, "rate", 0.0, 100000.0, &e->rate);
    optNumber(c, m, "spawn_height", -10.0, 10.0, &e->spawnHeight);
    optNumber(c, m, "jitter_radius", 0.0, 10.0, &e->jitterRadius);
    // Capacity is validated here, long before anything is allocated for it.
    bool capOk = optInteger(c, m, "capacity", 1, kMaxCapacity, &e->capacity);
    bool burstOk = optInteger(c, m, "burst", 0, kMaxCapacity, &e->burst);
    if (capOk && burstOk && e->burst > e->capacity) {
        const char* key = m.get("burst") ? "burst" : "capacity";
        c.report(ErrorCode::OutOfRange, m.get(key) ? m.get(key)->Mark() : node.Mark(),
                 m.path(key),
                 "expected burst <= capacity, got burst " + std::to_string(e->burst) +
                     " and capacity " + std::to_string(e->capacity));
    }
}

// The points of an over-life list (a colour ramp's stops, a curve's points): maps of a life
// fraction `t` in [0, 1] and one value `valueKey`, which readValue checks (reporting what is
// missing or wrong, at the point's mark `at` where the key is missing) and stores. Every point
// is read, and kept even where something is wrong, so that all errors are reported; `tMarks`
// gets where each point's t stands (the point's own mark without one) for the order check.
// Returns whether every point was read cleanly.
template <class Point, class ReadValue>
bool readLifePoints(YamlCheck& c, const Node& node, const std::string& p, const char* valueKey,
                    std::vector<Point>* points, std::vector<YAML::Mark>* tMarks, const ReadValue& readValue) {
    bool ok = true;
    size_t i = 0;
    for (auto it = node.begin(); it != node.end(); ++it, ++i) {
        const std::string sp = indexed(p, i);
        if (!c.isMap(*it, sp)) {
            ok = false;
            continue;
        }
        MapReader m(c, *it, sp, {"t", valueKey});
        Point point;
        const Node* t = m.get("t");
        if (!t) {
            c.report(ErrorCode::MissingKey, it->Mark(), m.path("t"),
                     "missing required key 't' (life fraction in [0, 1])");
            ok = false;
        } else {
            ok = c.number(*t, m.path("t"), 0.0, 1.0, &point.t) && ok;
        }
        ok = readValue(m, it->Mark(), &point) && ok;
        points->push_back(point);
        tMarks->push_back(t ? t->Mark() : it->Mark());
    }
    return ok;
}

// Whether the points' t never goes back. Reports each point whose t is below the previous one's
// (`noun` names them: "stop", "point"), or only the first such point when `firstOnly`.
template <class Point>
bool inLifeOrder(YamlCheck& c, const std::vector<Point>& points, const std::vector<YAML::Mark>& tMarks,
                 const std::string& p, const std::string& noun, bool firstOnly) {
    bool ok = true;
    for (size_t k = 1; k < points.size(); ++k) {
        if (points[k].t < points[k - 1].t) {
            c.report(ErrorCode::OutOfRange, tMarks[k], indexed(p, k) + ".t",
                     "expected t >= the previous " + noun + "'s " + std::to_string(points[k - 1].t) +
                         " (" + noun + "s in order of life), got " + std::to_string(points[k].t));
            ok = false;
            if (firstOnly) break;
        }
    }
    return ok;
}

// A whole over-life list of 1..maxPoints points (readLifePoints), stored in `out` only when every
// point is right and in order (inLifeOrder): a bad list leaves the previous one.
template <class Point, class ReadValue>
void readLifeList(YamlCheck& c, const Node& node, const std::string& p, int maxPoints, const char* valueKey,
                  const char* noun, bool firstOnly, std::vector<Point>* out, const ReadValue& readValue) {
    if (!c.isList(node, p, 1, maxPoints)) return;
    std::vector<Point> points;
    std::vector<YAML::Mark> tMarks;
    const bool ok = readLifePoints(c, node, p, valueKey, &points, &tMarks, readValue);
    if (ok && inLifeOrder(c, points, tMarks, p, noun, firstOnly)) *out = std::move(points);
}

// A colour ramp: 1-16 stops {t, rgba}; every stop out of order is reported.
void readColorRamp(YamlCheck& c, const Node& node, const std::string& p, std::vector<ColorStop>* out) {
    readLifeList(c, node, p, kMaxColorStops, "rgba", "stop", false, out,
                 [&](const MapReader& m, const YAML::Mark& at, ColorStop* stop) {
        const Node* rgba = m.get("rgba");
        if (!rgba) {
            c.report(ErrorCode::MissingKey, at, m.path("rgba"),
                     "missing required key 'rgba' ([r, g, b, a], each in [0, 1])");
            return false;
        }
        if (!c.isList(*rgba, m.path("rgba"), 4, 4)) return false;
        bool channelsOk = true;
        size_t j = 0;
        for (auto ct = rgba->begin(); ct != rgba->end(); ++ct, ++j) {
            channelsOk = c.number(*ct, indexed(m.path("rgba"), j), 0.0, 1.0, &stop->rgba[int(j)]) && channelsOk;
        }
        return channelsOk;
    });
}

// An over-life curve: 1-16 points {t, v}, t in [0, 1] non-decreasing, v in [lo, hi]; only the
// first point out of order is reported.
void readCurve(YamlCheck& c, const Node& node, const std::string& p, double lo, double hi,
               std::vector<CurvePoint>* out) {
    readLifeList(c, node, p, kMaxCurvePoints, "v", "point", true, out,
                 [&](const MapReader& m, const YAML::Mark& at, CurvePoint* point) {
        const Node* v = m.get("v");
        if (!v) {
            c.report(ErrorCode::MissingKey, at, m.path("v"),
                     "missing required key 'v' (a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "])");
            return false;
        }
        return c.number(*v, m.path("v"), lo, hi, &point->v);
    });
}

void readParticle(YamlCheck& c, const Node& node, const std::string& path, ParticleDesc* d) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path,
                {"lifetime", "start_size", "end_size", "size_variation", "rise_speed", "drag",
                 "wind_factor", "gravity", "spread_speed", "inherit_velocity", "spin", "fade_in", "fade_out",
                 "colour_ramp", "atlas", "alpha_over_life", "size_over_life"});
    optRange(c, m, "lifetime", 0.01, 60.0, &d->lifetimeMin, &d->lifetimeMax);
    optNumber(c, m, "start_size", 0.0, 10000.0, &d->startSize);
    optNumber(c, m, "end_size", 0.0, 10000.0, &d->endSize);
    optNumber(c, m, "size_variation", 0.0, 0.9, &d->sizeVariation);
    optNumber(c, m, "rise_speed", -50.0, 50.0, &d->riseSpeed);
    optNumber(c, m, "drag", 0.0, 1.0e6, &d->drag);
    optNumber(c, m, "wind_factor", 0.0, 10.0, &d->windFactor);
    optNumber(c, m, "gravity", 0.0, 100.0, &d->gravity);
    optNumber(c, m, "spread_speed", 0.0, 100.0, &d->spreadSpeed);
    optNumber(c, m, "inherit_velocity", 0.0, 2.0, &d->inheritVelocity);
    optRange(c, m, "spin", -50.0, 50.0, &d->spinMin, &d->spinMax);
    bool fadeOk = optNumber(c, m, "fade_in", 0.0, 1.0, &d->fadeIn);
    fadeOk = optNumber(c, m, "fade_out", 0.0, 1.0, &d->fadeOut) && fadeOk;
    if (fadeOk && d->fadeIn + d->fadeOut > 1.0f + 1e-6f) {
        const char* key = m.get("fade_out") ? "fade_out" : "fade_in";
        c.report(ErrorCode::OutOfRange, m.get(key) ? m.get(key)->Mark() : node.Mark(),
                 m.path(key),
                 "expected fade_in + fade_out <= 1, got " + std::to_string(d->fadeIn) + " + " +
                     std::to_string(d->fadeOut));
    }
    if (const Node* n = m.get("alpha_over_life")) {
        // The curve replaces the fades: both at once would leave the reader guessing which wins.
        for (const char* fadeKey : {"fade_in", "fade_out"}) {
            if (m.get(fadeKey)) {
                c.report(ErrorCode::OutOfRange, m.get(fadeKey)->Mark(), m.path(fadeKey),
                         std::string("expected either alpha_over_life or ") + fadeKey +
                             ", not both (the curve replaces fade_in and fade_out)");
            }
        }
        readCurve(c, *n, m.path("alpha_over_life"), 0.0, 1.0, &d->alphaOverLife);
    }
    if (const Node* n = m.get("size_over_life")) {
        readCurve(c, *n, m.path("size_over_life"), 0.0, 1.0, &d->sizeOverLife);
    }
    if (const Node* n = m.get("colour_ramp")) readColorRamp(c, *n, m.path("colour_ramp"), &d->colorRamp);
    if (const Node* n = m.get("atlas")) {
        const std::string p = m.path("atlas");
        if (c.isList(*n, p, 2, 2)) {
            int first = d->atlasFirst, count = d->atlasCount;
            bool ok = c.integer((*n)[0], p + "[0]", 0, 3, &first);
            ok = c.integer((*n)[1], p + "[1]", 1, 4, &count) && ok;
            if (ok && first + count > 4) {
                c.report(ErrorCode::OutOfRange, n->Mark(), p,
                         "expected [first, count] inside the 4 frames of the 2x2 atlas, got [" +
                             std::to_string(first) + ", " + std::to_string(count) + "]");
            } else if (ok) {
                d->atlasFirst = first;
                d->atlasCount = count;
            }
        }
    }
}

void readRender(YamlCheck& c, const Node& node, const std::string& path, RenderDesc* r) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path,
                {"technique", "blend", "softness", "contrast_power", "near_fade",
                 "sort_back_to_front"});
    if (const Node* n = m.get("technique")) {
        int i = 0;
        if (c.choice(*n, m.path("technique"), techniqueWords(), &i)) {
            const TechniqueRow& row = techniqueTable()[size_t(i)];
            r->stateless = row.stateless;
            r->technique = row.technique;
        }
    }
    optChoice(c, m, "blend", blendModeWords(), BlendMode::Alpha, &r->blend);
    optNumber(c, m, "softness", 1.0e-6, 1.0e6, &r->softness);
    optNumber(c, m, "contrast_power", 0.1, 16.0, &r->contrastPower);
    optNumber(c, m, "near_fade", 0.0, 100.0, &r->nearFade);
    if (const Node* n = m.get("sort_back_to_front")) {
        c.boolean(*n, m.path("sort_back_to_front"), &r->sortBackToFront);
    }
}

void readTurbulence(YamlCheck& c, const Node& node, const std::string& path, TurbulenceDesc* t) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"strength", "scale", "speed", "octaves"});
    optNumber(c, m, "strength", 0.0, 50.0, &t->strength);
    optNumber(c, m, "scale", 0.01, 1000.0, &t->scale);
    optNumber(c, m, "speed", 0.0, 100.0, &t->speed);
    optInteger(c, m, "octaves", 1, 6, &t->octaves);
}

void readVortex(YamlCheck& c, const Node& node, const std::string& path, VortexDesc* v) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"strength", "radius"});
    optNumber(c, m, "strength", -50.0, 50.0, &v->strength);
    optNumber(c, m, "radius", 0.01, 100.0, &v->radius);
}

void readLighting(YamlCheck& c, const Node& node, const std::string& path, LightingDesc* l) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"enabled", "normal_strength", "scattering", "anisotropy", "absorption",
                                "ambient", "casts_shadow"});
    if (const Node* n = m.get("enabled")) c.boolean(*n, m.path("enabled"), &l->enabled);
    optNumber(c, m, "normal_strength", 0.0, 1.0, &l->normalStrength);
    optNumber(c, m, "scattering", 0.0, 1.0, &l->scattering);
    optNumber(c, m, "anisotropy", -0.95, 0.95, &l->anisotropy);
    optNumber(c, m, "absorption", 0.0, 20.0, &l->absorption);
    optNumber(c, m, "ambient", 0.0, 2.0, &l->ambient);
    if (const Node* n = m.get("casts_shadow")) c.boolean(*n, m.path("casts_shadow"), &l->castsShadow);
}

void readMega(YamlCheck& c, const Node& node, const std::string& path, MegaDesc* g) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"resolution", "blur_radius", "noise_strength", "noise_scale"});
    optNumber(c, m, "resolution", 0.25, 1.0, &g->resolution);
    optNumber(c, m, "blur_radius", 0.0, 32.0, &g->blurRadius);
    optNumber(c, m, "noise_strength", 0.0, 1.0, &g->noiseStrength);
    optNumber(c, m, "noise_scale", 0.05, 100.0, &g->noiseScale);
}

// A stateless particle is a closed form of its age: nothing that needs the particle's path
// (turbulence, vortex) and nothing that needs sorting (it is drawn unsorted, so additive only).
void checkStateless(YamlCheck& c, const MapReader& m, const ReactionDesc& d) {
    for (const char* key : {"turbulence", "vortex"}) {
        const Node* n = m.get(key);
        const bool on = key[0] == 't' ? d.turbulence.enabled() : d.vortex.enabled();
        if (n && on) {
            c.report(ErrorCode::OutOfRange, n->Mark(), m.path(key),
                     std::string("expected no ") + key +
                         " with technique stateless (its particles follow a closed form of time; "
                         "use a CPU technique for turbulent motion)");
        }
    }
    if (d.render.blend != BlendMode::Additive) {
        const Node* render = m.get("render");
        YAML::Mark mark = render ? render->Mark() : YAML::Mark();
        if (render && render->IsMap() && (*render)["blend"]) mark = (*render)["blend"].Mark();
        c.report(ErrorCode::OutOfRange, mark, m.path("render") + ".blend",
                 std::string("expected blend additive with technique stateless (stateless particles are "
                             "drawn unsorted), got ") + blendModeName(d.render.blend));
    }
}

// One reaction, or the reactions of a layered one, appended to `outs` with the mark of each
// name (for duplicate reports). A layered reaction ({name, trigger, layers}) expands here into
// one reaction per layer, named "<name>.<layer name>", each with its own type, technique and
// blend, and a trigger read from the parent's trigger and then the layer's own: the layers fire
// together on the same contact, and the runtime and renderer see plain reactions.
struct ReadMarks {
    YAML::Mark name;      ///< the reaction's (layer's) name, else its first key
    YAML::Mark capacity;  ///< its emission.capacity, else its first key
};

void readReaction(YamlCheck& c, const Node& node, const std::string& path, bool isLayer,
                  const Node* parentTrigger, bool reportParentTrigger, const std::string& namePrefix,
                  std::vector<ReactionDesc>* outs, std::vector<ReadMarks>* marks) {
    if (!c.isMap(node, path)) return;
    MapReader m(c, node, path, {"name", "type", "trigger", "emission", "particle", "render",
                                "turbulence", "vortex", "lighting", "mega", "layers"});

    if (const Node* layers = m.get("layers")) {
        if (isLayer) {
            c.report(ErrorCode::OutOfRange, layers->Mark(), m.path("layers"),
                     "expected no layers inside a layer (layers nest one level)");
            return;
        }
        for (const char* key : {"type", "emission", "particle", "render", "turbulence", "vortex", "lighting", "mega"}) {
            if (const Node* n = m.get(key)) {
                c.report(ErrorCode::OutOfRange, n->Mark(), m.path(key),
                         std::string("expected only name, trigger and layers in a layered reaction; ") +
                             "move '" + key + "' into a layer");
            }
        }
        std::string name;
        if (const Node* n = m.get("name")) {
            c.name(*n, m.path("name"), &name);
        } else {
            c.report(ErrorCode::MissingKey, node.Mark(), m.path("name"),
                     "missing required key 'name' (a unique name for the reaction)");
        }
        if (!c.isList(*layers, m.path("layers"), 1, kMaxLayers)) return;
        size_t i = 0;
        for (auto it = layers->begin(); it != layers->end(); ++it, ++i) {
            // The parent's trigger is one key: its problems are reported with the first layer only.
            readReaction(c, *it, indexed(m.path("layers"), i), true, m.get("trigger"), i == 0,
                         name.empty() ? std::string() : name + ".", outs, marks);
        }
        return;
    }

    // The type decides the defaults, so it is read first; an invalid type validates the rest
    // against the wheel_smoke defaults (the reaction is rejected either way).
    ReactionType type = ReactionType::WheelSmoke;
    if (const Node* n = m.get("type")) {
        int i = 0;
        if (c.choice(*n, m.path("type"), reactionTypeWords(), &i)) type = static_cast<ReactionType>(i);
    } else {
        c.report(ErrorCode::MissingKey, node.Mark(), m.path("type"),
                 "missing required key 'type'; expected one of " + joined(reactionTypeWords()));
    }
    ReactionDesc d = defaultReaction(type);
    d.sourceFile = c.file();
    d.sourceLine = node.Mark().line + 1;
    d.sourceKey = path;

    YAML::Mark nameMark = node.Mark();
    if (const Node* n = m.get("name")) {
        c.name(*n, m.path("name"), &d.name);
        nameMark = n->Mark();
        // A layer's full name must still be a valid name (length).
        if (!d.name.empty() && !namePrefix.empty()) {
            d.name = namePrefix + d.name;
            if (d.name.size() > 64) {
                c.report(ErrorCode::OutOfRange, n->Mark(), m.path("name"),
                         "expected the layered name '" + d.name + "' to have at most 64 characters");
                d.name.clear();
            }
        } else if (isLayer && namePrefix.empty()) {
            d.name.clear();  // the parent's name was invalid: already reported
        }
    } else {
        c.report(ErrorCode::MissingKey, node.Mark(), m.path("name"),
                 "missing required key 'name' (a unique name for the reaction)");
    }
    // The parent's trigger (reported against its own key path, once: with the first layer).
    if (parentTrigger) {
        const std::string key = path.substr(0, path.rfind(".layers[")) + ".trigger";
        if (reportParentTrigger) {
            readTrigger(c, *parentTrigger, key, &d.trigger);
        } else {
            YamlCheck quiet(c.file(), nullptr);  // the same values, already reported
            readTrigger(quiet, *parentTrigger, key, &d.trigger);
        }
    }
    if (const Node* n = m.get("trigger")) readTrigger(c, *n, m.path("trigger"), &d.trigger);
    if (const Node* n = m.get("emission")) readEmission(c, *n, m.path("emission"), &d.emission);
    if (const Node* n = m.get("particle")) readParticle(c, *n, m.path("particle"), &d.particle);
    if (const Node* n = m.get("render")) readRender(c, *n, m.path("render"), &d.render);
    if (const Node* n = m.get("turbulence")) readTurbulence(c, *n, m.path("turbulence"), &d.turbulence);
    if (const Node* n = m.get("vortex")) readVortex(c, *n, m.path("vortex"), &d.vortex);
    if (const Node* n = m.get("lighting")) readLighting(c, *n, m.path("lighting"), &d.lighting);
    if (const Node* n = m.get("mega")) readMega(c, *n, m.path("mega"), &d.mega);
    if (d.render.stateless) checkStateless(c, m, d);
    YAML::Mark capacityMark = node.Mark();
    if (const Node* e = m.get("emission")) {
        if (e->IsMap() && (*e)["capacity"]) capacityMark = (*e)["capacity"].Mark();
    }
    outs->push_back(std::move(d));
    marks->push_back(ReadMarks{nameMark, capacityMark});
}

}  // namespace

void readReactionDocument(YamlCheck& c, const YAML::Node& root, std::vector<ReactionDesc>* out) {
    if (!c.isMap(root, "")) return;
    MapReader m(c, root, "", {"reactions"});
    const Node* list = m.get("reactions");
    if (!list) {
        c.report(ErrorCode::MissingKey, root.Mark(), "reactions",
                 "missing required key 'reactions' (a list of reactions, [] for none)");
        return;
    }
    if (!c.isList(*list, "reactions", 0, kMaxReactionsPerFile)) return;

    long long totalCapacity = 0;
    bool capacityReported = false;
    size_t i = 0;
    for (auto it = list->begin(); it != list->end(); ++it, ++i) {
        const std::string path = indexed("reactions", i);
        std::vector<ReactionDesc> read;
        std::vector<ReadMarks> marks;
        readReaction(c, *it, path, false, nullptr, false, std::string(), &read, &marks);
        for (size_t r = 0; r < read.size(); ++r) {
            ReactionDesc& d = read[r];
            if (d.name.empty()) continue;  // not a map, or no valid name: already reported
            for (const ReactionDesc& earlier : *out) {
                if (earlier.name == d.name) {
                    c.report(ErrorCode::DuplicateName, marks[r].name, d.sourceKey + ".name",
                             "reaction name '" + d.name + "' is already used at line " +
                                 std::to_string(earlier.sourceLine));
                    break;
                }
            }
            totalCapacity += d.emission.capacity;
            if (totalCapacity > kMaxTotalCapacity && !capacityReported) {
                // Blamed on the reaction (the layer) whose capacity crosses the limit.
                c.report(ErrorCode::OutOfRange, marks[r].capacity, d.sourceKey + ".emission.capacity",
                         "the reactions' capacities add up to more than " +
                             std::to_string(kMaxTotalCapacity) + " particles");
                capacityReported = true;
            }
            out->push_back(std::move(d));
        }
    }
}

}  // namespace fx
