// PNG files through libpng directly: the common output format must not pay
// for loading OpenImageIO and its ~260 shared libraries (half a second of
// start-up in every `kerf render`).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace kerf::render {

// Encodes 8-bit pixels (1 grey, 3 RGB or 4 RGBA channels, rows top to
// bottom) as the bytes of a PNG file into `file`. `srgb` marks colour
// images with PNG's sRGB chunk; `text` becomes tEXt chunks (keyword,
// Latin-1 value) before the image data. Returns an empty string on
// success, else what went wrong.
using PngText = std::vector<std::pair<std::string, std::string>>;
std::string encode_png(std::vector<unsigned char>& file, const std::uint8_t* pixels, int width, int height,
                       int channels, bool srgb, const PngText& text = {});

}  // namespace kerf::render
