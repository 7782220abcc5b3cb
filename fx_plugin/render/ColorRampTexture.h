#pragma once
// Colour by life: one kTexels-wide row per reaction, baked from the reaction's colour stops
// (sim/Lifecycle.h bakeColorRamp: piecewise linear, straight alpha) into an RGBA16F texture.
// Linear filtering along life, rows sampled at their texel centres (rowV()), so neighbouring
// reactions never mix.
//
// setRows() runs while passes are declared (no GL): it re-bakes only when some reaction's stops
// changed (hot reload) or the number of rows did; upload() (GL, inside a GlStateGuard) sends a
// changed table before drawing.
#include <cstdint>
#include <vector>

#include "reactions/ReactionDesc.h"

namespace fx {

struct ParticleBatch;

class ColorRampTexture {
public:
    static constexpr int kTexels = 64;  ///< keep equal to kRampTexels in particles_common.glsl

    ColorRampTexture() = default;
    ~ColorRampTexture();
    ColorRampTexture(const ColorRampTexture&) = delete;
    ColorRampTexture& operator=(const ColorRampTexture&) = delete;

    /// Row i is baked from ramps[i] (which must stay valid for this call only).
    void setRows(const std::vector<const std::vector<ColorStop>*>& ramps);
    /// Row i from batches[i]'s particle.colorRamp (opaque white for a batch without a desc).
    void setRows(const ParticleBatch* batches, int batchCount);
    /// Texture v coordinate of row `row`'s texel centres.
    float rowV(int row) const;
    /// Creates or re-specifies the texture when the table changed. Binds GL_TEXTURE_2D on the
    /// active unit and sets unpack state.
    void upload();
    uint32_t texture() const { return texture_; }
    int rows() const { return rows_; }

private:
    std::vector<const std::vector<ColorStop>*> inputs_;  ///< setRows(batches)' scratch
    std::vector<std::vector<ColorStop>> stops_;  ///< what each row was baked from
    std::vector<float> texels_;                  ///< rows_ x kTexels x RGBA
    int rows_ = 0;
    int uploadedRows_ = 0;
    bool dirty_ = true;
    uint32_t texture_ = 0;
};

}  // namespace fx
