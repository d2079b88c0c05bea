// A rendered image and how it is written to a file: the image/ room's public
// header (render.hpp produces Images, the CLI writes them).
#pragma once
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render/image/big_buffer.hpp"

namespace kerf::render {

// What the pixels mean; write_image() uses it to encode 8-bit files.
enum class ImageContent : std::uint8_t { Color, Depth, Normal, Hits };

// Row-major, row 0 at the top, `channels` interleaved floats per pixel.
// Colour is linear RGB; Depth: distance (+inf on miss); Normal: world unit
// vector (0 on miss); Hits: count of primitive intervals found.
// Rendered with RenderOptions::srgb8, `pixels` stays empty and `srgb8`
// holds the same layout as bytes: srgb_byte() of what pixels would hold.
struct Image {
    int width = 0, height = 0, channels = 0;
    BigVector<float> pixels;  // every element written by render()
    BigVector<std::uint8_t> srgb8;
    ImageContent content = ImageContent::Color;
    float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

class ImageWriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws ImageWriteError (one line) if write_image() could not write `path`:
// OpenImageIO has no writer for its extension, its folder is missing or
// refuses a new file, `path` is one of `inputs` (the same file by device and
// inode: another spelling, a symlink or a hard link), or the format cannot
// hold a `width` x `height` image (JPEG 2000 below 32 pixels; 0: not
// checked). The CLI calls it before evaluating and rendering, so a typo in
// -o costs nothing.
void check_output_path(const std::string& path, int width = 0, int height = 0,
                       const std::vector<std::string>& inputs = {});

// Format by extension (OpenImageIO). EXR/TIFF/HDR/PFM: linear float; others
// (PNG, JPEG, ...): 8-bit, colour sRGB-encoded, AOVs normalised (docs/spec.md §7).
// Encoded into memory, then written to a temporary file in the same folder
// with every write, fsync and close checked, and renamed over `path`: a
// failed write ("no space left on device") throws and leaves an existing
// file intact and no temporary behind (replace_file.hpp). `text`: PNG tEXt
// chunks (keyword, value) for a PNG file; other formats do not store it.
// `band_row`: for a band of a larger render written as PNG, the full
// image's row of the band's first row (png_file.hpp); -1 for an image.
// `on_encoded`, if given, is called once: for a PNG when its bytes are in
// memory, before the file is written and synced (the caller can free what
// it no longer needs while that waits for the device); otherwise after
// the file is written.
void write_image(const Image& image, const std::string& path,
                 const std::vector<std::pair<std::string, std::string>>& text = {}, int band_row = -1,
                 const std::function<void()>& on_encoded = {});

// Writes a file already encoded (a PNG joined from bands) as write_image()
// writes what it encodes: atomically, or to standard output for "-".
void write_encoded(const std::vector<unsigned char>& file, const std::string& path);

// Whether write_image() stores `path` in 8 bits (then a colour render can
// use RenderOptions::srgb8 and lose nothing).
bool is_8bit_output(const std::string& path);

// Whether write_image() writes `path` as PNG (its extension, or "-").
bool is_png_output(const std::string& path);

}  // namespace kerf::render
