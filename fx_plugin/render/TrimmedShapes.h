#pragma once
// Trimmed particles: per atlas frame, a convex polygon of at most kMaxVertices vertices that
// holds every point where sampling the atlas can return alpha > 0, drawn instead of the full quad
// so the fragments over the frame's transparent corners are never shaded.
//
// "Can return alpha > 0" covers the sampler, not only the base image: trilinear filtering reads
// mip levels whose texels cover 2^k base texels and blends each with its neighbours (bilinear:
// a texel reaches one texel beyond its centre, which near a cell border may be the next frame's).
// So there is one polygon per frame and per *LOD bucket*: bucket b holds the support of levels
// 0 .. b. A billboard facing the camera has one isotropic LOD over its whole area (its mapping to
// the screen is affine), so the vertex shader knows it: at LOD l the sampler reads level 0 alone
// when l <= 0 (magnification) and levels floor(l), floor(l) + 1 otherwise (trilinear; the
// particles' nearest-level sampler reads one of the two); with half a level of margin for the
// hardware's LOD approximation the shader takes bucket ceil(l + 0.5), clamped.
// Large particles (the costly ones) get the tight level-0 polygon; small ones the larger
// polygons of the coarse levels, where the saving no longer matters anyway.
//
// Coordinates are the particle's texture space: [-1, 1]^2, +y up, as atlasUV() takes them
// (particles_common.glsl); every polygon lies inside that square, so no fragment samples outside
// its cell's clamp range. Computed once when the atlas loads (a few ms for 512x512).
//
// Spherical billboards read the atlas at the ray's closest approach to the sphere's centre, in
// units of the radius, which always lies inside the unit disc. Their polygons (Clip::Disc) hold
// the same support clipped to that disc, and each comes with its inradius about the centre (the
// distance from (0, 0) to its nearest edge), by which the vertex shader grows it to bound the
// curved mapping from the screen to the atlas (vs_particles.glsl).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace fx {

class TrimmedShapes {
public:
    /// Which region the polygons bound: the frame's square (billboards) or the square's
    /// intersection with the unit disc (spherical billboards).
    enum class Clip { Square, Disc };

    static constexpr int kFrames = 4;       ///< the 2x2 atlas
    static constexpr int kMaxVertices = 8;  ///< per polygon (a triangle fan, padded)
    static constexpr int kMaxBuckets = 8;   ///< LOD buckets kept (coarser ones use the last)

    /// Computes the polygons of a 2x2 atlas of w x h straight-alpha RGBA8 texels (top row first),
    /// sampled with a mip chain of levels 0 .. maxLevel (box-filtered, as glGenerateMipmap).
    /// Returns false (and leaves the shapes empty) for sizes that are not an even w, h >= 2.
    bool compute(const uint8_t* rgba, int w, int h, int maxLevel);

    bool empty() const { return buckets_ == 0; }
    int buckets() const { return buckets_; }
    /// Polygon of `frame` for LOD bucket `bucket` (clamped), counter-clockwise, padded to
    /// kMaxVertices by repeating its last vertex (zero-area fan triangles).
    const std::array<glm::vec2, kMaxVertices>& polygon(int frame, int bucket, Clip clip = Clip::Square) const;
    /// Vertices before the padding.
    int vertexCount(int frame, int bucket, Clip clip = Clip::Square) const;
    /// Area of the polygon / area of the quad (4), for reports.
    float areaShare(int frame, int bucket, Clip clip = Clip::Square) const;
    /// Distance from the particle's centre (0, 0) to the nearest edge of the polygon; 0 when
    /// the centre is not strictly inside it (no polygon, or a puff drawn off centre).
    float inradius(int frame, int bucket, Clip clip = Clip::Square) const;
    /// Distance from the particle's centre (0, 0) to the polygon's farthest vertex (texture
    /// units: 1 is half the quad's edge), whatever the angle the polygon is turned by; sqrt(2)
    /// when there is no polygon.
    float reach(int frame, int bucket, Clip clip = Clip::Square) const;
    /// Packed for the vertex shader: [frame][bucket][vertex] as (x, y) pairs, two per vec4.
    std::vector<glm::vec4> packed(Clip clip = Clip::Square) const;
    /// (inradius(), areaShare()) of every [frame][bucket], two pairs per vec4
    /// (kFrames * buckets() / 2 of them).
    std::vector<glm::vec4> packedInfo(Clip clip) const;

    /// True when sampling can return alpha > 0 at texture-space point `p` of `frame` on mip level
    /// `level` (the test's reference; bilinear support of that level's non-zero texels).
    bool sampleSupport(int frame, int level, glm::vec2 p) const;
    /// Exact point-in-polygon (edges count as inside).
    static bool contains(const std::array<glm::vec2, kMaxVertices>& polygon, int count, glm::vec2 p);

private:
    struct Level {
        int w = 0, h = 0;
        std::vector<uint8_t> nonZero;  // per texel of the whole atlas at this level
    };
    std::vector<Level> levels_;
    int cellW_ = 0, cellH_ = 0;  // base level cell size in texels
    int buckets_ = 0;
    struct Table {
        std::array<std::array<std::array<glm::vec2, kMaxVertices>, kMaxBuckets>, kFrames> polygons{};
        std::array<std::array<int, kMaxBuckets>, kFrames> counts{};
    };
    const Table& table(Clip clip) const { return clip == Clip::Disc ? disc_ : square_; }
    Table square_, disc_;
};

}  // namespace fx
