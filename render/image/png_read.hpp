// Reading 8-bit PNG files back, checked end to end: `kerf assemble` joins
// tiles from them and `--resume` trusts a frame only if it reads whole.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace kerf::render {

struct PngPicture {
    int width = 0, height = 0, channels = 0;             // channels: 1 grey, 3 RGB, 4 RGBA
    std::vector<std::uint8_t> pixels;                    // rows top to bottom
    std::vector<std::pair<std::string, std::string>> text;  // tEXt chunks: keyword, value
    bool srgb = false;                                   // has an sRGB chunk
};

// Reads `path` into `picture`. Returns an empty string on success, else
// what is wrong ("not a PNG file", "CRC error", "missing IEND"): every
// chunk's CRC and the image data up to IEND are checked. Only
// non-interlaced 8-bit grey, RGB and RGBA files are accepted (what
// write_image() produces).
std::string read_png(const std::string& path, PngPicture& picture);

// The whole of file `path` into `bytes`: an empty string, or "cannot open
// it" / "cannot read it" (read_png's and read_png_band's first checks).
std::string read_file_bytes(const std::string& path, std::vector<unsigned char>& bytes);

}  // namespace kerf::render
