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
// success, else what went wrong. The image data is cut into pieces
// (png_pieces.hpp); for a band of a larger render (`kerf render --tile`),
// `band_row` is the full image's row of the band's first row: the pieces
// are cut where the full image's are and their table is written as the
// text chunk kPiecesKeyword, so `kerf assemble` can join them undecoded.
using PngText = std::vector<std::pair<std::string, std::string>>;
std::string encode_png(std::vector<unsigned char>& file, const std::uint8_t* pixels, int width, int height,
                       int channels, bool srgb, const PngText& text = {}, int band_row = -1);

// The same file around image data already deflated: `idat` is a whole zlib
// stream (png_pieces.hpp's zlib_stream()).
std::string png_from_stream(std::vector<unsigned char>& file, const std::vector<unsigned char>& idat, int width,
                            int height, int channels, bool srgb, const PngText& text = {});

}  // namespace kerf::render
