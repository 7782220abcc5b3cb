// The C boundary's options (fx/fx.h, "Options"): fxRenderOptions, the 2.0 setters kept for 2.0
// hosts, and the scene light.
#include <cstddef>
#include <string>

#include "CApiEntries.h"
#include "WorldBasis.h"

namespace fx {
namespace capi {
namespace {

// An int from the C side into one of the API's uint8_t enums: a value outside 0..255 would wrap
// into a valid one, so it is clamped to 255, which every setter refuses.
template <class Enum>
Enum enumFrom(int v) {
    return static_cast<Enum>(v < 0 || v > 255 ? 255 : v);
}

// API 2.0's fxRenderOptions ended with bilinearUpsample; 2.1 appended particleShape and
// quarterResAlways.
constexpr size_t kRenderOptionsSize20 = offsetof(fxRenderOptions, particleShape);
// 2.3 appended tiled: a 2.1 or 2.2 host's size ends before it; 2.4 tiling.
constexpr size_t kRenderOptionsSize21 = offsetof(fxRenderOptions, tiled);
constexpr size_t kRenderOptionsSize23 = offsetof(fxRenderOptions, tiling);
bool knownOptionsSize(uint32_t size) {
    return knownSize(size, sizeof(fxRenderOptions), kRenderOptionsSize20) || size == kRenderOptionsSize21 ||
           size == kRenderOptionsSize23;
}

}  // namespace

int setRenderOptions(fxPlugin* p, const fxRenderOptions* o) {
    if (!usable(p, "setRenderOptions")) return handleError(p);
    if (!o) return code(refuse(p, ErrorCode::NullArgument, "setRenderOptions", "options is null"));
    if (!knownOptionsSize(o->size)) {
        return code(refuse(p, ErrorCode::BadDescriptor, "setRenderOptions",
                           sizeProblem("fxRenderOptions", o->size, sizeof *o, kRenderOptionsSize20) + " (or " +
                               std::to_string(kRenderOptionsSize21) + ": API 2.1-2.2, " +
                               std::to_string(kRenderOptionsSize23) + ": API 2.3)"));
    }
    const fxRenderOptions full = fullDesc(*o);
    if (full.techniqueOverride < 0 || full.techniqueOverride > FX_TECHNIQUE_MEGA) {
        return code(refuse(p, ErrorCode::InvalidValue, "setRenderOptions",
                           "techniqueOverride = " + std::to_string(full.techniqueOverride) +
                               "; expected FromReaction, Hard, Soft, Spherical or Mega"));
    }
    // A 2.0 host's struct has no shape: its call leaves the shape setParticleShape gave.
    const bool setsShape = o->size > kRenderOptionsSize20;
    if (setsShape && full.particleShape != FX_SHAPE_TRIMMED && full.particleShape != FX_SHAPE_QUAD) {
        return code(refuse(p, ErrorCode::InvalidValue, "setRenderOptions",
                           "particleShape = " + std::to_string(full.particleShape) +
                               "; expected FX_SHAPE_TRIMMED (0) or FX_SHAPE_QUAD (1)"));
    }
    const bool setsTiling = o->size > kRenderOptionsSize23;
    if (setsTiling && (full.tiling < FX_TILING_AUTO || full.tiling > FX_TILING_ON)) {
        return code(refuse(p, ErrorCode::InvalidValue, "setRenderOptions",
                           "tiling = " + std::to_string(full.tiling) +
                               "; expected FX_TILING_AUTO (0), FX_TILING_OFF (1) or FX_TILING_ON (2)"));
    }
    RenderOptions r;
    r.techniqueOverride = static_cast<Technique>(full.techniqueOverride);
    r.quarterRes = full.quarterRes != 0;
    r.bilinearUpsample = full.bilinearUpsample != 0;
    // Like the shape, a 2.0 host's call leaves quarterResAlways as it was.
    r.quarterResAlways = setsShape ? full.quarterResAlways != 0 : impl(p).renderOptions().quarterResAlways;
    // And a 2.0-2.2 host's call leaves tiled as it was.
    r.tiled = o->size > kRenderOptionsSize21 ? full.tiled != 0 : impl(p).renderOptions().tiled;
    // And a 2.0-2.3 host's call leaves tiling as it was.
    r.tiling = setsTiling ? static_cast<Tiling>(full.tiling) : impl(p).renderOptions().tiling;
    const ErrorCode set = impl(p).setRenderOptions(r);
    if (set != ErrorCode::None || !setsShape) return code(set);
    return code(impl(p).setParticleShape(static_cast<ParticleShape>(full.particleShape)));
}
void getRenderOptions(const fxPlugin* p, fxRenderOptions* out) {
    if (!outSet(p, out, "getRenderOptions")) return;
    const RenderOptions r = impl(p).renderOptions();
    fxRenderOptions full = fxDescInit_<fxRenderOptions>();
    full.techniqueOverride = static_cast<int>(r.techniqueOverride);
    full.quarterRes = r.quarterRes ? 1 : 0;
    full.bilinearUpsample = r.bilinearUpsample ? 1 : 0;
    full.particleShape = static_cast<int>(impl(p).particleShape());
    full.quarterResAlways = r.quarterResAlways ? 1 : 0;
    full.tiled = r.tiled ? 1 : 0;
    full.tiling = static_cast<int>(r.tiling);
    // 2.0 filled its fields whatever the size (hosts may never have set it on a struct they only
    // read): a size the library does not know still gets them, and only them, as every host's
    // struct has at least those.
    writeOut(out, full, knownOptionsSize(out->size) ? out->size : kRenderOptionsSize20);
}

int setParticleShape(fxPlugin* p, int s) {
    if (!usable(p, "setParticleShape")) return handleError(p);
    return code(impl(p).setParticleShape(enumFrom<ParticleShape>(s)));
}
int particleShape(const fxPlugin* p) { return usable(p, "particleShape") ? int(impl(p).particleShape()) : 0; }
int setQuarterResEdges(fxPlugin* p, int m) {
    if (!usable(p, "setQuarterResEdges")) return handleError(p);
    return code(impl(p).setQuarterResEdges(enumFrom<QuarterResEdges>(m)));
}
int quarterResEdges(const fxPlugin* p) { return usable(p, "quarterResEdges") ? int(impl(p).quarterResEdges()) : 0; }
int setFadeClassification(fxPlugin* p, int m) {
    if (!usable(p, "setFadeClassification")) return handleError(p);
    return code(impl(p).setFadeClassification(enumFrom<FadeClassification>(m)));
}
int fadeClassification(const fxPlugin* p) {
    return usable(p, "fadeClassification") ? int(impl(p).fadeClassification()) : 0;
}
int setFadeClassCounting(fxPlugin* p, fxBool on) {
    if (!usable(p, "setFadeClassCounting")) return handleError(p);
    return code(impl(p).setFadeClassCounting(on != 0));
}
void fadeClassCounts(const fxPlugin* p, fxFadeClassCounts* out) {
    if (!outSet(p, out, "fadeClassCounts")) return;
    const FadeClassCounts c = impl(p).fadeClassCounts();
    *out = fxFadeClassCounts{c.fadeNeeded, c.inFront, c.hidden, c.counted ? 1 : 0};
}
int setSceneLight(fxPlugin* p, const fxSceneLight* l) {
    if (!usable(p, "setSceneLight")) return handleError(p);
    if (!l) return code(refuse(p, ErrorCode::NullArgument, "setSceneLight", "light is null"));
    if (!knownSize(l->size, sizeof *l)) {
        return code(refuse(p, ErrorCode::BadDescriptor, "setSceneLight", sizeProblem("fxSceneLight", l->size, sizeof *l)));
    }
    SceneLight s;
    s.toSun = toPluginWorld(p->up, glm::vec3(l->toSun[0], l->toSun[1], l->toSun[2]));
    s.sunColor = glm::vec3(l->sunColor[0], l->sunColor[1], l->sunColor[2]);
    s.ambient = glm::vec3(l->ambient[0], l->ambient[1], l->ambient[2]);
    return code(impl(p).setSceneLight(s));
}
void clearSceneLight(fxPlugin* p) {
    if (usable(p, "clearSceneLight")) impl(p).clearSceneLight();
}

}  // namespace capi
}  // namespace fx
