// Bands of one render (`kerf render --tile`) joined into the PNG file of
// the whole image without decoding most of them: every piece of the full
// image (png_pieces.hpp) that lies wholly inside one band is that band's
// deflated bytes as they are; only the pieces a band edge cuts are decoded
// from the two bands and deflated again. Decoding and deflating every row
// again took more time than the rest of `kerf assemble` together.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/image/png_pieces.hpp"

namespace kerf::render {

// A PNG file read into memory with its chunks checked but its image data
// not decoded.
struct PngBand {
    int width = 0, height = 0, channels = 0;                 // channels: 1 grey, 3 RGB, 4 RGBA
    std::vector<std::pair<std::string, std::string>> text;  // tEXt chunks: keyword, value
    bool srgb = false;                                       // has an sRGB chunk
    int first_row = -1;              // from the pieces table (png_file.hpp); -1: the file has none
    std::vector<unsigned char> stream;  // the zlib stream: all IDAT data
    std::vector<PieceData> pieces;      // views into `stream`, top to bottom

    PngBand() = default;
    PngBand(PngBand&&) = default;  // the pieces point into `stream`: moved, never copied
    PngBand& operator=(PngBand&&) = default;
};

// Reads `path` into `band`. Returns an empty string on success, else what
// is wrong ("not a PNG file", "the file ends early", "IDAT: CRC error"):
// every chunk's CRC up to IEND is checked, the header must be a
// non-interlaced 8-bit grey, RGB or RGBA image, and a pieces table must
// match the image data's size, framing and Adler-32.
std::string read_png_band(const std::string& path, PngBand& band);

// Decodes all of `band`'s rows into `pixels` (width * height * channels
// bytes). It must have a pieces table. Returns an empty string, else what
// is wrong.
std::string decode_band(const PngBand& band, std::uint8_t* pixels);

// The PNG file of the image whose rows are `bands`, top to bottom (each
// with a pieces table, its first_row where the one above ends, all of one
// width, channel count and sRGB flag), without text chunks: the bytes
// encode_png() gives for the whole image. Returns an empty string, else
// what is wrong, and sets `culprit` to the band whose data it is in (or
// null when none is).
std::string join_png_bands(std::vector<unsigned char>& file, const std::vector<const PngBand*>& bands,
                           const PngBand** culprit = nullptr);

}  // namespace kerf::render
