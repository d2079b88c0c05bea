// The codecs of the light image module (codec_module.cpp): EXR through
// OpenEXR, TIFF through libtiff, JPEG through libjpeg, each encoding into
// memory (kerf writes the bytes, replace_file.cpp) and reading a file into
// RGB floats for textures. Every failure is returned as a message, never
// thrown through the module's C interface and never an exit().
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace kerf::codec {

using Bytes = std::vector<unsigned char>;

// `pixels`: rows top to bottom, `channels` interleaved (1 grey, 3 RGB, 4
// RGBA with alpha premultiplied, as kerf stores it for float formats).
// Each returns "" on success, else why it failed.
std::string encode_exr(const float* pixels, int width, int height, int channels, Bytes& out);
std::string encode_tiff(const void* pixels, bool as_float, int width, int height, int channels, Bytes& out);
std::string encode_jpeg(const std::uint8_t* pixels, int width, int height, int channels, Bytes& out);

// An image read for a texture: 3 channels (grey replicated, channels past
// the third dropped), rows top to bottom; `encoded` when the file stores
// integers (kerf takes them as sRGB), not floats (linear).
struct Pixels {
    int width = 0, height = 0;
    std::vector<float> rgb;
    bool encoded = true;
};
std::string read_exr(const std::string& path, Pixels& out);
std::string read_tiff(const std::string& path, Pixels& out);
std::string read_jpeg(const std::string& path, Pixels& out);

// Keeps the first three channels of `n` (grey replicated) of every pixel.
inline void to_rgb(const float* in, int n, std::size_t count, std::vector<float>& rgb) {
    rgb.resize(count * 3);
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = in[i * n + (n >= 3 ? c : 0)];
}

// Textures past 2^28 pixels are refused (as the OpenImageIO reader does).
inline bool sane_size(int width, int height) {
    return width > 0 && height > 0 && std::size_t(width) * std::size_t(height) <= (std::size_t(1) << 28);
}

}  // namespace kerf::codec
