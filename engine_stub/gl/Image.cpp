#include "gl/Image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <climits>
#include <vector>

#include "textio/SafeFile.h"

namespace cube {

bool writePng(const std::string& path, const ImageRGBA8& image, std::string* error) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height) * 4u) {
        *error = path + ": no image to write (empty frame)";
        return false;
    }
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4)) {
        *error = path + ": cannot write PNG (folder missing or not writable?)";
        return false;
    }
    return true;
}

bool readPng(const std::string& path, ImageRGBA8* image, std::string* error) {
    // Through the shared opener: regular files only, never blocking on a FIFO, 64 MiB at most.
    std::vector<unsigned char> bytes;
    std::string why;
    if (!textio::readFileBounded(path, size_t(64) << 20, &bytes, nullptr, &why)) {
        *error = path + ": cannot read image: " + why;
        return false;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* data = bytes.size() > size_t(INT_MAX)
                              ? nullptr
                              : stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &n, 4);
    if (!data) {
        *error = path + ": cannot read image (" + (stbi_failure_reason() ? stbi_failure_reason() : "?") + ")";
        return false;
    }
    image->width = w;
    image->height = h;
    image->pixels.assign(data, data + size_t(w) * size_t(h) * 4u);
    stbi_image_free(data);
    return true;
}

}  // namespace cube
