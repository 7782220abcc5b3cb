#pragma once
// The smoke texture atlas (000 sections 2.12 and 3.3.6): data/smoke_atlas.png, 2x2 frames of
// straight-alpha RGBA8 puffs, row-major from the top-left. Uploaded unflipped (t = 0 is the
// image's top row; particles_common.glsl's atlasUV() accounts for it) with a full mip chain,
// trilinear filtering, clamp to edge (the particle programs read it bilinearly from the nearest
// level: ParticleDraw's atlas sampler). Every cell's border has alpha exactly 0, so neither
// filtering nor the rotated texture coordinates pull a neighbouring frame in.
#include <cstdint>
#include <string>

#include "TrimmedShapes.h"

namespace fx {

class SmokeAtlas {
public:
    static constexpr const char* kFileName = "smoke_atlas.png";
    /// Its normal map (tools/make_assets): RGB = the signed particle-space normal as
    /// 128 + 127 n (x right, y up, z toward the viewer; exactly 0 where the atlas alpha is 0),
    /// A = height. Same size, same frames.
    static constexpr const char* kNormalsFileName = "smoke_normals.png";

    SmokeAtlas() = default;
    ~SmokeAtlas();
    SmokeAtlas(const SmokeAtlas&) = delete;
    SmokeAtlas& operator=(const SmokeAtlas&) = delete;

    /// Loads `dataDir`/smoke_atlas.png, or the copy embedded in the library when `dataDir` is
    /// empty (stb_image), and uploads it. Changes GL_TEXTURE_2D on the
    /// active unit and the unpack state: call inside a GlStateGuard. On failure returns false
    /// with "path: reason" in *error and holds no texture.
    bool load(const std::string& dataDir, std::string* error);
    uint32_t texture() const { return texture_; }
    /// The lit atlas lit programs sample instead: R, G = the normal map's x and y, B = the
    /// atlas's grey (R of the atlas; its RGB is grey), A = the atlas's alpha; same size, filtering
    /// and mip chain. Without a loadable normal map R = G = 128 (flat cards) and normalsError()
    /// says why.
    uint32_t litTexture() const { return litTexture_; }
    bool hasNormals() const { return normalsError_.empty(); }
    const std::string& normalsError() const { return normalsError_; }
    int width() const { return width_; }
    int height() const { return height_; }
    /// Per frame and LOD bucket, the polygon that holds every texel the sampler can return with
    /// alpha > 0 (TrimmedShapes.h); computed at load.
    const TrimmedShapes& shapes() const { return shapes_; }
    /// Base-level texels across one frame (the vertex shader's LOD estimate).
    int cellTexels() const { return width_ / 2; }

private:
    uint32_t texture_ = 0;
    uint32_t litTexture_ = 0;
    std::string normalsError_;
    int width_ = 0, height_ = 0;
    TrimmedShapes shapes_;
};

}  // namespace fx
