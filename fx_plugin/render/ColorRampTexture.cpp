#include "ColorRampTexture.h"

#include "render/PrivateGl.h"

#include "DrawList.h"
#include "../sim/Lifecycle.h"

namespace fx {
namespace {

bool sameStops(const std::vector<ColorStop>& a, const std::vector<ColorStop>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].t != b[i].t || a[i].rgba != b[i].rgba) return false;
    }
    return true;
}

const std::vector<ColorStop>& whiteRamp() {
    static const std::vector<ColorStop> kWhite{ColorStop{0.0f, glm::vec4(1.0f)}};
    return kWhite;
}

}  // namespace

ColorRampTexture::~ColorRampTexture() {
    if (texture_) glDeleteTextures(1, &texture_);
}

void ColorRampTexture::setRows(const ParticleBatch* batches, int batchCount) {
    inputs_.clear();
    for (int b = 0; b < batchCount; ++b) {
        inputs_.push_back(batches[b].desc ? &batches[b].desc->particle.colorRamp : &whiteRamp());
    }
    setRows(inputs_);
}

void ColorRampTexture::setRows(const std::vector<const std::vector<ColorStop>*>& ramps) {
    const int rows = static_cast<int>(ramps.size());
    bool changed = rows != rows_;
    for (int i = 0; i < rows && !changed; ++i) changed = !sameStops(*ramps[size_t(i)], stops_[size_t(i)]);
    if (!changed) return;
    rows_ = rows;
    stops_.resize(size_t(rows));
    texels_.assign(size_t(rows > 0 ? rows : 1) * kTexels * 4, 1.0f);
    for (int i = 0; i < rows; ++i) {
        stops_[size_t(i)] = *ramps[size_t(i)];
        bakeColorRamp(stops_[size_t(i)], kTexels, texels_.data() + size_t(i) * kTexels * 4);
    }
    dirty_ = true;
}

float ColorRampTexture::rowV(int row) const {
    const int height = rows_ > 0 ? rows_ : 1;
    return (float(row) + 0.5f) / float(height);
}

void ColorRampTexture::upload() {
    if (!dirty_ && texture_) return;
    if (texels_.empty()) texels_.assign(size_t(kTexels) * 4, 1.0f);
    const int height = rows_ > 0 ? rows_ : 1;
    if (!texture_) glGenTextures(1, &texture_);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    if (height != uploadedRows_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, kTexels, height, 0, GL_RGBA, GL_FLOAT,
                     texels_.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        uploadedRows_ = height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kTexels, height, GL_RGBA, GL_FLOAT, texels_.data());
    }
    dirty_ = false;
}

}  // namespace fx
