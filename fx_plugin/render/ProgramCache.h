#pragma once
// The plugin's programs, one cache (Renderers owns it) keyed by what a program is built for.
// Key::program names the shader pair: Billboard, the particle draw (below), or one of the fixed
// programs of the other passes (the quarter-res depth downsample, half-res z-fill and
// composite's two builds; the opacity map's; the immediate path's depth lineariser; the five
// mega passes'; the stateless particles'; the tiled path's five and its lists' four), whose files and defines are
// in ProgramCache.cpp beside the billboards'.
// A billboard key is the variant a batch draws with:
//   variant          the technique's shaders and target kind (vs_particles + ...):
//     HardZBuffer      fs_particles_hard                         (full res, z-buffer test)
//     HardLinearDepth  fs_particles_hard, FX_LINEAR_DEPTH_TEST   (quarter res)
//     Soft             fs_particles_soft  (contrast_power whole or half-whole, <= 16: multiplies
//                                          and a sqrt)
//     Spherical        fs_particles_spherical, FX_SPHERICAL
//     SoftGeneralPower fs_particles_soft, FX_GENERAL_POWER (any contrast_power: pow)
//   lit              FX_LIT: particles_common.glsl's smokeLight, for reactions under a scene light
//   power            FX_POWER_STEPS = 2 contrast_power: Soft with the curve's multiplies folded
//                    (power 1 draws no curve at all); -1 = no power folded
//   halfRes          FX_HALF_RES_DEPTH: Soft, SoftGeneralPower and Spherical drawn at quarter res,
//                    reading the plugin's half-res linear depth as it is (no decode); HardLinearDepth
//                    is quarter res only and always reads it so
// Key::bits() packs them with the program; nothing else names a program. The resolution path is in the variant
// (quarter res draws HardLinearDepth for hard) and halfRes; the depth convention is no variant: the
// programs decode the depth the pass hands them, and reversed-Z changes only the depth function the
// pass sets.
//
// Contract:
//  - build(keys) is the only call that compiles. It runs from prepareGl and a shader reload (and,
//    for a host that changed options or reactions without calling prepareGl again, from
//    declarePasses before any pass); get() and find() never compile, so no pass ever does.
//  - Each key is tried once per cache: a failure is appended to *errors once ("file:line:
//    message" lines) and the key stays unbuilt; the other keys still build.
//  - Every build of one cache reads the one snapshot it was made with (ShaderLoader.h): a
//    variant built later is built from the files that went live, never a later broken edit.
//  - A draw asks for drawKey() of its batch, filtered to the programs that exist (filter(), after
//    Filament's filterVariant): the full-res build where the halfRes one is missing (it reads the
//    half-res depth through the decode, which the quarter-res pass sets to the identity), unlit
//    where the variant's lit build is missing, the variant's general build where the power's own is
//    missing; no key where the variant itself did not build: its technique is not drawn
//    (usableTechniques), the others still are. The fallback lives there alone; find() of the
//    filtered key is the program.
//  - A pass program's uniforms are its user's (QuarterResPrograms, SmokeOpacityMap,
//    DepthLinearizer, MegaPrograms, StatelessRenderer: bind), looked up on passProgram() once per
//    build; a billboard's are looked up here once per build.
//  - A shader reload builds a new cache of keys() and swap()s it in whole: the users hold this
//    object, whose contents change, and bind again.
//  - Changes no bound GL state (no glUseProgram); deletes every program it built.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/TextIo.h"
#include "fx/Plugin.h"

#include "FogUniforms.h"
#include "SceneDepthSource.h"

namespace fx {

/// Uniform locations shared by every particle program (-1 where a program does not use one).
struct ParticleProgram {
    uint32_t program = 0;
    int view = -1, proj = -1, nearPlane = -1, farPlane = -1, slopeMax = -1;
    int rampRow = -1, blendMode = -1, softScale = -1, contrastPower = -1, nearFade = -1;
    int atlas = -1, ramp = -1, sceneDepth = -1;
    SceneDepthUniforms depthDecode;
    FogUniforms fog;
    int trimmed = -1, shapeBuckets = -1, lodScale = -1, shapes = -1, shapeInfo = -1, pixelSlope = -1;
    int powerWhole = -1, powerHalf = -1;
    // FX_LIT only.
    int sunView = -1, sunColor = -1, ambient = -1, normalStrength = -1, scattering = -1, anisotropy = -1,
        absorption = -1, shadowed = -1, viewToShadow = -1, opacity = -1;
};

class ProgramCache {
public:
    enum Variant : int { HardZBuffer = 0, HardLinearDepth, Soft, Spherical, SoftGeneralPower, VariantCount };
    /// The shader pair a key builds. Billboard: the particle draw of a variant; the others are
    /// the passes' fixed programs (no variant, lit or power: those stay at their defaults).
    enum Program : int {
        Billboard = 0,
        DepthDownsample,    ///< vs_particles_tiles + fs_particles_depth_downsample
        HalfZ,              ///< vs_particles_tiles + fs_particles_half_z
        Composite,          ///< vs_particles_tiles + fs_particles_composite (depth-aware)
        CompositeBilinear,  ///< the same, FX_COMPOSITE_BILINEAR
        OpacityMap,         ///< vs_particles + fs_particles_opacity
        LinearizeDepth,     ///< vs_particles_fullscreen + fs_particles_linearize_depth
        MegaDepth,          ///< vs_particles_fullscreen + fs_mega_depth
        MegaSpheres,        ///< vs_mega + fs_mega_spheres
        MegaBlur,           ///< vs_particles_fullscreen + fs_mega_blur
        MegaShade,          ///< the same, FX_MEGA_SHADE
        MegaComposite,      ///< vs_particles_fullscreen + fs_mega_composite
        Stateless,          ///< vs_stateless_particles + fs_stateless_particles
        TiledShade,         ///< cs_particles_tiled (compute: TiledPath.h)
        TiledComposite,     ///< vs_particles_tiles + fs_particles_tiled_composite
        TiledSetup,         ///< cs_particles_tiled, FX_TILED_SETUP
        TileEmit,           ///< cs_particles_tile_sort, FX_TILE_EMIT (compute: TileSort.h)
        TileSortCount,      ///< the same, FX_TILE_COUNT
        TileSortScan,       ///< the same, FX_TILE_SCAN
        TileSortScatter,    ///< the same, FX_TILE_SCATTER
        TiledShadeLit,      ///< cs_particles_tiled, FX_LIT (lit smoke: TiledPath.h)
        TiledSetupLit,      ///< cs_particles_tiled, FX_TILED_SETUP and FX_LIT
        TileOrderKey,       ///< cs_particles_tile_sort, FX_TILE_ORDER_KEY (TileSort::DepthOrder)
        TileOrderBatch,     ///< the same, FX_TILE_ORDER_BATCH
        TileOrderPrefix,    ///< the same, FX_TILE_ORDER_PREFIX
        TileOrderAdd,       ///< the same, FX_TILE_ORDER_ADD
        TileBound,          ///< the same, FX_TILE_BOUND (the GPU's bins: TileSort::binOnGpu)
        TileList,           ///< the same, FX_TILE_LIST
        ProgramCount
    };

    struct Key {
        Variant variant = HardZBuffer;
        bool lit = false;
        int powerSteps = -1;  ///< 2 contrast_power, 0 .. kMaxPowerSteps; -1: none (Soft only)
        Program program = Billboard;
        bool halfRes = false;  ///< drawn at quarter res, on the plugin's half-res depth (not HardLinearDepth)
        /// This billboard key without its power: the variant's general build (lit, halfRes kept).
        Key general() const { return Key{variant, lit, -1, Billboard, halfRes}; }
        /// The key of a pass's fixed program.
        static Key of(Program p) {
            Key k;
            k.program = p;
            return k;
        }
        /// variant in bits 0-2, lit 3, powerSteps + 1 in 4-9, program in 10-14, halfRes 15.
        uint32_t bits() const;
        /// The #defines that select this variant (prepended to each stage).
        std::string defines() const;
        bool operator==(const Key& o) const { return bits() == o.bits(); }
    };

    static constexpr int kMaxPowerSteps = 32;  ///< contrast_power 16

    /// A cache with no sources: every build fails (for a renderer not loaded yet).
    ProgramCache() = default;
    /// Every build reads `snapshot` (snapshotShaderReader: one version of each file).
    explicit ProgramCache(ShaderReader snapshot) : read_(std::move(snapshot)) {}
    ~ProgramCache();
    ProgramCache(const ProgramCache&) = delete;
    ProgramCache& operator=(const ProgramCache&) = delete;
    /// Exchanges every program, key and the snapshot with `other` (a reload's new cache goes live;
    /// the old programs are deleted with `other`). No GL.
    void swap(ProgramCache& other) noexcept;
    /// No program built (then destroying it makes no GL call).
    bool empty() const { return built_.empty(); }

    /// Builds each key of `keys` not tried before; appends one "file:line: message" block per
    /// key that failed. Returns how many programs it compiled.
    int build(const std::vector<Key>& keys, std::vector<std::string>* errors);
    /// The program of `key`, or null where it was never built or failed. Never builds.
    const ParticleProgram* find(const Key& key) const;
    bool tried(const Key& key) const { return tried_.count(key.bits()) != 0; }
    /// The GL program of a pass's fixed program `p`, 0 where it was never built or failed. Never
    /// builds.
    uint32_t passProgram(Program p) const;
    /// The variant's general build (program 0 when it did not build). Never builds.
    const ParticleProgram& get(Variant v, bool lit = false) const;
    /// find(filter(...)) of a batch of `v` with `contrastPower` (program 0 where none exists).
    const ParticleProgram& get(Variant v, bool lit, float contrastPower) const;
    /// The key a batch of `technique` with `contrastPower` asks for: its variant, `lit`, and for
    /// Soft with a whole or half-whole power that power's folded build. Not filtered.
    static Key drawKey(Technique technique, bool quarterRes, float contrastPower, bool lit);
    /// `wanted` reduced to a program that was built (see the contract above); a key find() gives
    /// null for where the variant's general build is missing. Never builds.
    Key filter(Key wanted) const;
    /// Every key tried (built or failed), in the order tried: a reload builds the same set anew.
    const std::vector<Key>& keys() const { return order_; }
    /// techniqueBit() mask of the techniques drawable on a full-res or a quarter-res target.
    uint32_t usableTechniques(bool quarterRes) const;

    /// Every variant, lit and unlit: what prepareGl always builds (a technique whose general
    /// program fails is not drawn; the run-time override can pick any of them).
    static std::vector<Key> techniqueKeys();
    /// The general halfRes builds, lit and unlit: what prepareGl adds while quarter res is on.
    static std::vector<Key> halfResKeys();
    /// The billboard renderer's fixed programs (the quarter-res passes', the opacity map's): what
    /// its loading builds with techniqueKeys (a failed one turns its pass off: quarter res draws
    /// at full res, lit smoke goes without self-shadowing). The lineariser's is the immediate
    /// path's own (ImmediateRenderer::prepare).
    static std::vector<Key> passKeys();
    /// The mega renderer's five programs (MegaRenderer: built when mega is loaded).
    static std::vector<Key> megaKeys();
    /// Adds (once each) the keys a batch of `technique` with `contrastPower` draws with, lit and
    /// unlit, on a quarter-res target or not (drawKey).
    static void addDrawKeys(Technique technique, float contrastPower, bool quarterRes, std::vector<Key>* keys);
    /// The tiled path's fifteen programs (TiledPath.h: unlit and lit, with tileSortKeys and tileBinKeys): what
    /// prepareGl adds while it is on, in a context with compute shaders (lit too, as
    /// techniqueKeys: a host may set a scene light at any time).
    static std::vector<Key> tiledKeys();
    /// The eight that write the tiled path's lists (TileSort.h): the four of the lists, then the
    /// four that sort the particles of a list built without its order.
    static std::vector<Key> tileSortKeys();
    /// The two that bin a view's particles on the GPU (TileSort::binOnGpu).
    static std::vector<Key> tileBinKeys();
    /// `contrastPower` picks between the two soft programs (see above).
    static Variant variantFor(Technique technique, bool quarterRes, float contrastPower = 1.0f);
    /// contrast_power = whole + half / 2 with whole in [0, 16], half 0 or 1: true and the split.
    static bool halfWholePower(float contrastPower, int* whole, int* half);

private:
    ShaderReader read_;
    std::unordered_map<uint32_t, ParticleProgram> built_;
    std::unordered_set<uint32_t> tried_;
    std::vector<Key> order_;
};

}  // namespace fx
