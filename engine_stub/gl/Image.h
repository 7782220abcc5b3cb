#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace cube {

/// An 8-bit RGBA image, rows top-down.
struct ImageRGBA8 {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;
};

/// Writes a PNG with stb_image_write (creates no folders). False + error naming the path.
bool writePng(const std::string& path, const ImageRGBA8& image, std::string* error);
/// Reads a PNG into RGBA8 with stb_image. False + error naming the path.
bool readPng(const std::string& path, ImageRGBA8* image, std::string* error);

}  // namespace cube
