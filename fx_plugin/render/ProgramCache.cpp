#include "ProgramCache.h"

#include <cmath>
#include <utility>

#include "render/PrivateGl.h"

#include "DrawList.h"
#include "ShaderLoader.h"

namespace fx {
namespace {

struct Source {
    const char* vertex;
    const char* fragment;
    const char* defines;
};

// Every key's files and defines: the billboards' by variant, then the passes' fixed programs by
// ProgramCache::Program (from DepthDownsample on).
constexpr Source kSources[ProgramCache::VariantCount + ProgramCache::ProgramCount - 1] = {
    {"vs_particles.glsl", "fs_particles_hard.glsl", ""},
    {"vs_particles.glsl", "fs_particles_hard.glsl", "#define FX_LINEAR_DEPTH_TEST 1\n#define FX_HALF_RES_DEPTH 1\n"},
    {"vs_particles.glsl", "fs_particles_soft.glsl", ""},
    {"vs_particles.glsl", "fs_particles_spherical.glsl", "#define FX_SPHERICAL 1\n"},
    {"vs_particles.glsl", "fs_particles_soft.glsl", "#define FX_GENERAL_POWER 1\n"},
    {"vs_particles_tiles.glsl", "fs_particles_depth_downsample.glsl", ""},
    {"vs_particles_tiles.glsl", "fs_particles_half_z.glsl", ""},
    {"vs_particles_tiles.glsl", "fs_particles_composite.glsl", ""},
    {"vs_particles_tiles.glsl", "fs_particles_composite.glsl", "#define FX_COMPOSITE_BILINEAR 1\n"},
    {"vs_particles.glsl", "fs_particles_opacity.glsl", ""},
    {"vs_particles_fullscreen.glsl", "fs_particles_linearize_depth.glsl", ""},
    {"vs_particles_fullscreen.glsl", "fs_mega_depth.glsl", ""},
    {"vs_mega.glsl", "fs_mega_spheres.glsl", ""},
    {"vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", ""},
    {"vs_particles_fullscreen.glsl", "fs_mega_blur.glsl", "#define FX_MEGA_SHADE 1\n"},
    {"vs_particles_fullscreen.glsl", "fs_mega_composite.glsl", ""},
    {"vs_stateless_particles.glsl", "fs_stateless_particles.glsl", ""},
    {"cs_particles_tiled.glsl", "", "#define FX_GENERAL_POWER 1\n"},
    {"vs_particles_tiles.glsl", "fs_particles_tiled_composite.glsl", ""},
    {"cs_particles_tiled.glsl", "", "#define FX_TILED_SETUP 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_EMIT 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_COUNT 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_SCAN 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_SCATTER 1\n"},
    {"cs_particles_tiled.glsl", "", "#define FX_GENERAL_POWER 1\n#define FX_LIT 1\n"},
    {"cs_particles_tiled.glsl", "", "#define FX_TILED_SETUP 1\n#define FX_LIT 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_ORDER_KEY 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_ORDER_BATCH 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_ORDER_PREFIX 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_ORDER_ADD 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_BOUND 1\n"},
    {"cs_particles_tile_sort.glsl", "", "#define FX_TILE_LIST 1\n"},
};

const Source& sourceOf(const ProgramCache::Key& key) {
    return kSources[key.program == ProgramCache::Billboard ? int(key.variant)
                                                           : ProgramCache::VariantCount + key.program - 1];
}

ParticleProgram locate(GLuint program) {
    ParticleProgram p;
    p.program = program;
    p.view = glGetUniformLocation(program, "uView");
    p.proj = glGetUniformLocation(program, "uProj");
    p.nearPlane = glGetUniformLocation(program, "uNear");
    p.farPlane = glGetUniformLocation(program, "uFar");
    p.slopeMax = glGetUniformLocation(program, "uSlopeMax");
    p.rampRow = glGetUniformLocation(program, "uRampRow");
    p.blendMode = glGetUniformLocation(program, "uBlendMode");
    p.softScale = glGetUniformLocation(program, "uSoftScale");
    p.contrastPower = glGetUniformLocation(program, "uContrastPower");
    p.nearFade = glGetUniformLocation(program, "uNearFadeMap");
    p.atlas = glGetUniformLocation(program, "uAtlas");
    p.ramp = glGetUniformLocation(program, "uRamp");
    p.sceneDepth = glGetUniformLocation(program, "uSceneDepth");
    p.depthDecode.locate(program);
    p.trimmed = glGetUniformLocation(program, "uTrimmed");
    p.shapeBuckets = glGetUniformLocation(program, "uShapeBuckets");
    p.lodScale = glGetUniformLocation(program, "uLodScale");
    p.shapes = glGetUniformLocation(program, "uShapes");
    p.shapeInfo = glGetUniformLocation(program, "uShapeInfo");
    p.pixelSlope = glGetUniformLocation(program, "uPixelSlope");
    p.powerWhole = glGetUniformLocation(program, "uPowerWhole");
    p.powerHalf = glGetUniformLocation(program, "uPowerHalf");
    p.sunView = glGetUniformLocation(program, "uSunView");
    p.sunColor = glGetUniformLocation(program, "uSunColor");
    p.ambient = glGetUniformLocation(program, "uAmbient");
    p.normalStrength = glGetUniformLocation(program, "uNormalStrength");
    p.scattering = glGetUniformLocation(program, "uScattering");
    p.anisotropy = glGetUniformLocation(program, "uAnisotropy");
    p.absorption = glGetUniformLocation(program, "uAbsorption");
    p.shadowed = glGetUniformLocation(program, "uShadowed");
    p.viewToShadow = glGetUniformLocation(program, "uViewToShadow");
    p.opacity = glGetUniformLocation(program, "uOpacity");
    p.fog = FogUniforms::of(program);
    return p;
}

void addOnce(const ProgramCache::Key& key, std::vector<ProgramCache::Key>* keys) {
    for (const ProgramCache::Key& k : *keys) {
        if (k == key) return;
    }
    keys->push_back(key);
}

const ParticleProgram kNone{};

}  // namespace

uint32_t ProgramCache::Key::bits() const {
    static_assert(ProgramCount <= 32, "program takes bits 10-14");
    return uint32_t(variant) | (lit ? 1u << 3 : 0u) | (uint32_t(powerSteps + 1) << 4) | (uint32_t(program) << 10) |
           (halfRes ? 1u << 15 : 0u);
}

std::string ProgramCache::Key::defines() const {
    std::string d;
    // The quarter-res downsample and composites gather four depths in one fetch where the context
    // has ARB_texture_gather (GL 4.0 hardware); declared only then, since a declaration the
    // compiler does not know is a warning on the host's debug output.
    const bool gathers = program == DepthDownsample || program == Composite || program == CompositeBilinear ||
                         program == MegaComposite;
    if (gathers && FXGLAD_GL_ARB_texture_gather) d += "#extension GL_ARB_texture_gather : require\n#define FX_GATHER 1\n";
    // The depth-aware composite gathers the footprint's farthest depths too (a component other
    // than red: ARB_gpu_shader5) and reads the full-resolution depth only where they span an edge.
    if (program == Composite && FXGLAD_GL_ARB_texture_gather && FXGLAD_GL_ARB_gpu_shader5) {
        d += "#extension GL_ARB_gpu_shader5 : require\n#define FX_GATHER_FARTHEST 1\n";
    }
    d += sourceOf(*this).defines;
    if (halfRes) d += "#define FX_HALF_RES_DEPTH 1\n";
    if (powerSteps >= 0) d += "#define FX_POWER_STEPS " + std::to_string(powerSteps) + "\n";
    if (lit) d += "#define FX_LIT 1\n";
    return d;
}

ProgramCache::~ProgramCache() {
    for (auto& entry : built_) glDeleteProgram(entry.second.program);
}

void ProgramCache::swap(ProgramCache& other) noexcept {
    std::swap(read_, other.read_);
    built_.swap(other.built_);
    tried_.swap(other.tried_);
    order_.swap(other.order_);
}

int ProgramCache::build(const std::vector<Key>& keys, std::vector<std::string>* errors) {
    int compiled = 0;
    for (const Key& key : keys) {
        if (tried(key)) continue;
        tried_.insert(key.bits());
        order_.push_back(key);
        const Source& source = sourceOf(key);
        std::string error;
        const GLuint program = read_ ? buildProgram(read_, source.vertex, source.fragment, key.defines(), &error) : 0;
        if (read_) ++compiled;
        if (!program) {
            errors->push_back(read_ ? error : std::string(source.fragment) +
                                                  ":0: the particle programs have no shader sources");
            continue;
        }
        if (key.program == Billboard) {
            built_[key.bits()] = locate(program);
        } else {
            built_[key.bits()].program = program;  // its user looks its uniforms up
        }
    }
    return compiled;
}

const ParticleProgram* ProgramCache::find(const Key& key) const {
    const auto it = built_.find(key.bits());
    return it == built_.end() ? nullptr : &it->second;
}

uint32_t ProgramCache::passProgram(Program p) const {
    const ParticleProgram* built = find(Key::of(p));
    return built ? built->program : 0;
}

const ParticleProgram& ProgramCache::get(Variant v, bool lit) const {
    const ParticleProgram* p = find(Key{v, lit, -1});
    return p ? *p : kNone;
}

const ParticleProgram& ProgramCache::get(Variant v, bool lit, float contrastPower) const {
    int whole = 0, half = 0;
    const int steps = v == Soft && halfWholePower(contrastPower, &whole, &half) ? 2 * whole + half : -1;
    const ParticleProgram* p = find(filter(Key{v, lit, steps}));
    return p ? *p : kNone;
}

ProgramCache::Key ProgramCache::drawKey(Technique technique, bool quarterRes, float contrastPower, bool lit) {
    const Variant v = variantFor(technique, quarterRes, contrastPower);
    int whole = 0, half = 0;
    const int steps = v == Soft && halfWholePower(contrastPower, &whole, &half) ? 2 * whole + half : -1;
    // HardLinearDepth is half-res by its defines.
    return Key{v, lit, steps, Billboard, quarterRes && v != HardLinearDepth};
}

ProgramCache::Key ProgramCache::filter(Key wanted) const {
    // The full-res build reads the half-res depth correctly too (through an identity decode).
    if (wanted.halfRes && !find(Key{wanted.variant, false, -1, Billboard, true})) wanted.halfRes = false;
    if (wanted.lit && !find(Key{wanted.variant, true, -1, Billboard, wanted.halfRes})) {
        wanted.lit = false;
    }
    const Key general = wanted.general();
    // A power's own build stands in for nothing when the variant's general one is missing.
    if (wanted.powerSteps < 0 || !find(general) || !find(wanted)) return general;
    return wanted;
}

std::vector<ProgramCache::Key> ProgramCache::techniqueKeys() {
    std::vector<Key> keys;
    for (bool lit : {false, true}) {
        for (int v = 0; v < VariantCount; ++v) keys.push_back(Key{Variant(v), lit, -1});
    }
    return keys;
}

std::vector<ProgramCache::Key> ProgramCache::halfResKeys() {
    std::vector<Key> keys;
    for (bool lit : {false, true}) {
        for (Variant v : {Soft, SoftGeneralPower, Spherical}) keys.push_back(Key{v, lit, -1, Billboard, true});
    }
    return keys;
}

std::vector<ProgramCache::Key> ProgramCache::passKeys() {
    std::vector<Key> keys;
    for (Program p : {DepthDownsample, HalfZ, Composite, CompositeBilinear, OpacityMap}) keys.push_back(Key::of(p));
    return keys;
}

std::vector<ProgramCache::Key> ProgramCache::megaKeys() {
    std::vector<Key> keys;
    for (Program p : {MegaDepth, MegaSpheres, MegaBlur, MegaShade, MegaComposite}) keys.push_back(Key::of(p));
    return keys;
}

std::vector<ProgramCache::Key> ProgramCache::tiledKeys() {
    std::vector<Key> keys = {Key::of(TiledSetup), Key::of(TiledShade), Key::of(TiledComposite),
                             Key::of(TiledSetupLit), Key::of(TiledShadeLit)};
    for (const Key& k : tileSortKeys()) keys.push_back(k);
    for (const Key& k : tileBinKeys()) keys.push_back(k);
    return keys;
}

std::vector<ProgramCache::Key> ProgramCache::tileBinKeys() { return {Key::of(TileBound), Key::of(TileList)}; }

std::vector<ProgramCache::Key> ProgramCache::tileSortKeys() {
    return {Key::of(TileEmit),     Key::of(TileSortCount),  Key::of(TileSortScan),    Key::of(TileSortScatter),
            Key::of(TileOrderKey), Key::of(TileOrderBatch), Key::of(TileOrderPrefix), Key::of(TileOrderAdd)};
}

void ProgramCache::addDrawKeys(Technique technique, float contrastPower, bool quarterRes, std::vector<Key>* keys) {
    for (bool lit : {false, true}) {
        const Key key = drawKey(technique, quarterRes, contrastPower, lit);
        addOnce(key.general(), keys);
        if (key.powerSteps >= 0) addOnce(key, keys);
    }
}

bool ProgramCache::halfWholePower(float contrastPower, int* whole, int* half) {
    const float twice = 2.0f * contrastPower;
    const float rounded = std::round(twice);
    if (!(std::fabs(twice - rounded) <= 1e-6f * std::fmax(1.0f, twice)) || rounded < 0.0f || rounded > 32.0f) {
        return false;
    }
    const int steps = int(rounded);
    *whole = steps / 2;
    *half = steps % 2;
    return true;
}

ProgramCache::Variant ProgramCache::variantFor(Technique technique, bool quarterRes, float contrastPower) {
    switch (technique) {
    case Technique::Hard: return quarterRes ? HardLinearDepth : HardZBuffer;
    case Technique::Spherical: return Spherical;
    case Technique::Soft:
    case Technique::Mega:  // drawn by its own renderer; soft where a billboard stands in
    case Technique::FromReaction: break;
    }
    int whole = 0, half = 0;
    return halfWholePower(contrastPower, &whole, &half) ? Soft : SoftGeneralPower;
}

uint32_t ProgramCache::usableTechniques(bool quarterRes) const {
    uint32_t mask = 0;
    for (Technique t : {Technique::Hard, Technique::Soft, Technique::Spherical}) {
        if (get(variantFor(t, quarterRes)).program) mask |= techniqueBit(t);
    }
    // Soft draws with either soft program (by contrast_power): both or neither.
    if (!get(SoftGeneralPower).program) mask &= ~techniqueBit(Technique::Soft);
    return mask;
}

}  // namespace fx
