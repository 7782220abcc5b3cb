#include "SmokeAtlas.h"

#include <vector>

#include "render/PrivateGl.h"
#include <stb_image.h>

#include "base/TextIo.h"
#include "render/EmbeddedResources.h"

namespace fx {

SmokeAtlas::~SmokeAtlas() {
    if (texture_) glDeleteTextures(1, &texture_);
    if (litTexture_) glDeleteTextures(1, &litTexture_);
}

namespace {

// `dataDir`/`fileName`, or the embedded copy when `dataDir` is empty, decoded to RGBA8.
// Null with "path: reason" in *error on failure; free with stbi_image_free.
stbi_uc* decodePng(const std::string& dataDir, const char* fileName, const char* what, int* w, int* h,
                   std::string* error) {
    int channels = 0;
    stbi_uc* pixels = nullptr;
    std::string path;
    if (dataDir.empty()) {
        path = std::string("<embedded>/") + fileName;
        const embedded::Resource* r = embedded::find(fileName);
        if (r) pixels = stbi_load_from_memory(r->data, int(r->size), w, h, &channels, 4);
    } else {
        // Read through SafeFile (regular files only, never blocking, at most 64 MiB), decode
        // from memory.
        path = dataDir + "/" + fileName;
        std::string bytes, why;
        if (!fxio::readFileBounded(path, size_t(64) << 20, &bytes, nullptr, &why)) {
            *error = path + ": cannot load " + what + " (" + why + ")";
            return nullptr;
        }
        pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), w,
                                       h, &channels, 4);
    }
    if (!pixels) {
        const char* why = stbi_failure_reason();
        *error = path + ": cannot load " + what + " (" + (why ? why : "unknown reason") + ")";
    }
    return pixels;
}

// Uploads RGBA8 `pixels` into `*texture` (created if 0) with a mip chain down to `maxLevel`.
void upload(uint32_t* texture, const stbi_uc* pixels, int w, int h, int maxLevel) {
    if (!*texture) glGenTextures(1, texture);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindTexture(GL_TEXTURE_2D, *texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, maxLevel);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

bool SmokeAtlas::load(const std::string& dataDir, std::string* error) {
    int w = 0, h = 0;
    stbi_uc* pixels = decodePng(dataDir, kFileName, "the smoke atlas", &w, &h, error);
    if (!pixels) return false;
    if (w < 2 || h < 2 || (w % 2) || (h % 2)) {
        stbi_image_free(pixels);
        *error = (dataDir.empty() ? std::string("<embedded>") : dataDir) + "/" + kFileName + ": expected a 2x2 atlas with even width and height, got " +
                 std::to_string(w) + "x" + std::to_string(h);
        return false;
    }
    // Stop the mip chain while a frame is still 8 texels wide: below that, the 2x2 frames would
    // average into each other.
    int maxLevel = 0;
    for (int cell = (w < h ? w : h) / 2; cell > 8; cell /= 2) ++maxLevel;
    shapes_.compute(pixels, w, h, maxLevel);  // the trimmed polygons of this image and mip chain
    upload(&texture_, pixels, w, h, maxLevel);

    // The lit atlas: the normal map's x and y with the atlas's grey and alpha (see the header).
    // The normal map is optional (without it lit smoke is drawn as flat cards: x = y = 0), but
    // it must match the atlas's size.
    normalsError_.clear();
    int nw = 0, nh = 0;
    stbi_uc* normals = decodePng(dataDir, kNormalsFileName, "the smoke normal map", &nw, &nh, &normalsError_);
    if (normals && (nw != w || nh != h)) {
        normalsError_ = (dataDir.empty() ? std::string("<embedded>") : dataDir) + "/" + kNormalsFileName +
                        ": expected the atlas's size " + std::to_string(w) + "x" + std::to_string(h) + ", got " +
                        std::to_string(nw) + "x" + std::to_string(nh);
        stbi_image_free(normals);
        normals = nullptr;
    }
    std::vector<stbi_uc> lit(size_t(w) * size_t(h) * 4);
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        lit[i * 4 + 0] = normals ? normals[i * 4 + 0] : 128;
        lit[i * 4 + 1] = normals ? normals[i * 4 + 1] : 128;
        lit[i * 4 + 2] = pixels[i * 4 + 0];
        lit[i * 4 + 3] = pixels[i * 4 + 3];
    }
    if (normals) stbi_image_free(normals);
    stbi_image_free(pixels);
    upload(&litTexture_, lit.data(), w, h, maxLevel);
    width_ = w;
    height_ = h;
    return true;
}

}  // namespace fx
