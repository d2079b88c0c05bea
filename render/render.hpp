// The renderer's public API (issue 5): a lowered csg::Scene in, an image out.
// The CLI (`kerf render`) is a thin layer over render() and write_image().
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/image/big_buffer.hpp"

#include "csg/scene.hpp"

namespace kerf::render {

enum class Aov : std::uint8_t { None, Depth, Normal, Hits };

struct RenderOptions {
    int width = 800, height = 600;
    int spp = 1;                     // samples per pixel (stratified jitter when > 1)
    int threads = 0;                 // 0: all hardware threads
    bool preview = false;            // 1 spp, no reflections (same resolution)
    Aov aov = Aov::None;             // AOVs trace one ray through each pixel centre
    std::optional<std::array<int, 4>> crop;  // x0, y0, x1, y1: half-open, full-image pixels
    std::uint64_t seed = 0;          // jitter seed; pixels are seeded by (seed, x, y)
    bool double_precision = true;    // false: primitives intersected in float
    int max_reflect_depth = 4;
    // Colour only: store 8-bit sRGB codes (Image::srgb8) instead of linear
    // floats, for 8-bit files: a quarter of the memory, and fresh memory is
    // expensive (the kernel clears every page; 13 % of a 2048² render).
    bool srgb8 = false;
};

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

// Totals over the whole image (the caller divides for per-ray means).
struct RenderStats {
    std::uint64_t primary_rays = 0, shadow_rays = 0, reflect_rays = 0;
    double seconds = 0;
    std::uint64_t union_ops = 0, difference_ops = 0, intersection_ops = 0;
    std::uint64_t interval_tests = 0;  // ray–primitive intersections computed
    std::uint64_t rays() const { return primary_rays + shadow_rays + reflect_rays; }
};

// Throws std::invalid_argument for bad options (size, spp, crop outside the
// image) and std::runtime_error if Embree fails. `progress` receives the
// finished fraction from render threads, one call at a time.
Image render(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr,
             std::function<void(double fraction)> progress = {});

class ImageWriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws ImageWriteError (one line) if write_image() could not write `path`:
// OpenImageIO has no writer for its extension, or its folder is missing or
// refuses a new file. The CLI calls it before evaluating and rendering, so a
// typo in -o costs nothing.
void check_output_path(const std::string& path);

// Format by extension (OpenImageIO). EXR/TIFF/HDR/PFM: linear float; others
// (PNG, JPEG, ...): 8-bit, colour sRGB-encoded, AOVs normalised (spec §7).
// Written to a temporary file in the same folder, then renamed over `path`,
// so a failed write leaves an existing file intact.
void write_image(const Image& image, const std::string& path);

// Whether write_image() stores `path` in 8 bits (then a colour render can
// use RenderOptions::srgb8 and lose nothing).
bool is_8bit_output(const std::string& path);

}  // namespace kerf::render
