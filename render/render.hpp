// The renderer's public API: a lowered csg::Scene in, an image out
// (render/image/image.hpp writes it). The CLI (`kerf render`) is a thin
// layer over render() and write_image().
#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "csg/scene.hpp"
#include "render/image/image.hpp"
#include "render/path_lighting.hpp"

namespace kerf::render {

enum class Aov : std::uint8_t { None, Depth, Normal, Hits };
// --alpha: a fourth channel, the share of a pixel's samples that hit a
// solid (background 0). Straight for PNG (colour = the hit samples' mean),
// premultiplied for EXR/TIFF (colour = their sum over all samples), as
// those formats expect.
enum class Alpha : std::uint8_t { None, Straight, Premultiplied };

// --integrator (docs/spec.md §12): the Whitted-style shader (shading.hpp,
// the default) or the path tracer (integrator_path.hpp).
enum class Integrator : std::uint8_t { Whitted, Path };

struct RenderOptions {
    int width = 800, height = 600;
    int spp = 1;                     // uniform: samples per pixel (stratified jitter when > 1)
    // Adaptive anti-aliasing (adaptive.hpp; the CLI's default): a sample at
    // each pixel centre, then, where a neighbour hit another surface or
    // differs by more than aa_threshold (0..1, a display channel), corner
    // probes, a straight edge located to 1/2^⌈log2 aa_samples⌉ of a side, or
    // aa_samples stratified samples (the pattern of spp = aa_samples).
    // Replaces `spp`.
    bool adaptive = false;
    int aa_samples = 16;
    double aa_threshold = 0.05;
    int threads = 0;                 // 0: all hardware threads
    Alpha alpha = Alpha::None;       // colour renders only
    bool preview = false;            // 1 spp, no reflections (same resolution)
    Aov aov = Aov::None;             // AOVs trace one ray through each pixel centre
    std::optional<std::array<int, 4>> crop;  // x0, y0, x1, y1: half-open, full-image pixels
    std::uint64_t seed = 0;          // jitter seed; pixels are seeded by (seed, x, y)
    bool double_precision = true;    // false: primitives intersected in float
    int max_reflect_depth = 4;      // reflections and refractions into solids one ray may branch into (--max-depth)
    // Path: `spp` paths per pixel, uniformly (adaptive sampling does not
    // apply: every pixel is noisy), at most max_path_depth bounces each
    // (--max-depth with --integrator path). preview and AOVs stay Whitted's.
    Integrator integrator = Integrator::Whitted;
    int max_path_depth = 16;
    PathLighting path_lighting = PathLighting::Mis;  // tests compare the estimators
    // Progressive path tracing: the paths of a pixel are traced in passes of
    // 1, 1, 2, 4, 8, ... (a total of 1, 2, 4, 8, ... up to spp), and after
    // each pass `on_pass` receives the whole region's image so far and the
    // paths per pixel in it. The last pass's image is byte for byte the one
    // a render without passes gives. time_limit > 0 (seconds, from the start
    // of render(), the BVH build included): no pass starts after it; the image then has fewer paths
    // (RenderStats::paths_per_pixel says how many).
    std::function<void(const Image&, int paths_per_pixel)> on_pass;
    double time_limit = 0;
    // Colour only: store 8-bit sRGB codes (Image::srgb8) instead of linear
    // floats, for 8-bit files: a quarter of the memory, and fresh memory is
    // expensive (the kernel clears every page; 13 % of a 2048² render).
    bool srgb8 = false;
    // When given and set (by another thread), the render stops at the next
    // tile and render() throws RenderCancelled: an interactive viewer drops
    // a render the moment the view moves (docs/spec.md §13).
    const std::atomic<bool>* cancel = nullptr;
};

class RenderCancelled : public std::runtime_error {
public:
    RenderCancelled() : std::runtime_error("render cancelled") {}
};

// Totals over the whole image (the caller divides for per-ray means).
struct RenderStats {
    std::uint64_t primary_rays = 0, shadow_rays = 0, reflect_rays = 0, refract_rays = 0;  // refract: rays inside solids
    double seconds = 0;
    std::uint64_t union_ops = 0, difference_ops = 0, intersection_ops = 0;
    std::uint64_t interval_tests = 0;  // ray–primitive intersections computed
    std::uint64_t refined_pixels = 0;  // adaptive anti-aliasing: pixels given aa_samples
    std::uint64_t edge_pixels = 0;     // adaptive anti-aliasing: pixels whose straight edge was located
    int paths_per_pixel = 0;           // the path integrator: paths in each pixel of the image
    std::uint64_t rays() const { return primary_rays + shadow_rays + reflect_rays + refract_rays; }
};

// Throws std::invalid_argument for bad options (size, spp, crop outside the
// image), std::runtime_error if Embree fails, RenderCancelled when
// options.cancel was set. `progress` receives the
// finished fraction from render threads, one call at a time; its first call,
// progress(0), says the BVHs are built and tracing starts.
Image render(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr,
             std::function<void(double fraction)> progress = {});

}  // namespace kerf::render
