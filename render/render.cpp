// Tiles, threads, samples and AOVs (README.md). Every pixel depends only on
// (scene, options, seed, its full-image coordinates), so thread count and
// crop never change a pixel's value.
#include "render/render.hpp"

#include <xmmintrin.h>
#include <pmmintrin.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/camera.hpp"
#include "render/tracer/tracer.hpp"
#include "render/shading.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

namespace {

constexpr int kTile = 32;

std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double uniform01(std::uint64_t& state) { return double(splitmix64(state) >> 11) * 0x1.0p-53; }

// Sample i of n inside the unit pixel: a k×k jittered grid when n = k², else
// n strata per axis with the y strata permuted by a golden-ratio step
// (Latin-hypercube style), so any n covers the pixel evenly.
glm::dvec2 sample_offset(int i, int n, std::uint64_t& rng) {
    const double jx = uniform01(rng), jy = uniform01(rng);
    const int k = int(std::lround(std::sqrt(double(n))));
    if (k * k == n) return {(i % k + jx) / k, (i / k + jy) / k};
    int step = std::max(1, int(std::lround(n * 0.6180339887)));
    while (std::gcd(step, n) != 1) ++step;
    return {(i + jx) / n, (int((std::int64_t(i) * step) % n) + jy) / n};
}

void check_options(const RenderOptions& o) {
    if (o.width < 1 || o.height < 1) throw std::invalid_argument("image size must be at least 1×1");
    if (o.spp < 1) throw std::invalid_argument("samples per pixel must be at least 1");
    if (o.threads < 0) throw std::invalid_argument("thread count must not be negative");
    if (o.crop) {
        const auto& c = *o.crop;
        if (c[0] < 0 || c[1] < 0 || c[2] > o.width || c[3] > o.height || c[0] >= c[2] || c[1] >= c[3])
            throw std::invalid_argument("crop rectangle must lie inside the image and not be empty");
    }
}

}  // namespace

Image render(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats,
             std::function<void(double)> progress) {
    check_options(options);
    const auto start = std::chrono::steady_clock::now();
    // Embree builds its BVHs with TBB: inside the arena, so `threads` bounds
    // the build as well as the rendering.
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    std::optional<CsgTracer> built;
    arena.execute([&] { built.emplace(scene, !options.double_precision); });
    const CsgTracer& tracer = *built;
    const int spp = options.preview ? 1 : options.spp;
    const Shader shader(scene, tracer, options.preview ? 0 : options.max_reflect_depth);
    const CameraModel camera(scene.camera, options.width, options.height);

    const std::array<int, 4> region = options.crop ? *options.crop
                                                   : std::array<int, 4>{0, 0, options.width, options.height};
    Image image;
    image.width = region[2] - region[0];
    image.height = region[3] - region[1];
    switch (options.aov) {
        case Aov::None: image.channels = 3; image.content = ImageContent::Color; break;
        case Aov::Depth: image.channels = 1; image.content = ImageContent::Depth; break;
        case Aov::Normal: image.channels = 3; image.content = ImageContent::Normal; break;
        case Aov::Hits: image.channels = 1; image.content = ImageContent::Hits; break;
    }
    const bool to_bytes = options.srgb8 && options.aov == Aov::None;
    const std::size_t values = std::size_t(image.width) * image.height * image.channels;
    if (to_bytes) image.srgb8.resize(values); else image.pixels.resize(values);  // not zeroed
    const SrgbTable& srgb = srgb_table();
    // A colour pixel's three values: linear floats, or their sRGB codes.
    auto store = [&](int x, int y, const glm::dvec3& c) {
        const std::size_t at = (std::size_t(y - region[1]) * image.width + std::size_t(x - region[0])) * 3;
        if (to_bytes) {
            image.srgb8[at] = srgb_byte(srgb, float(c.x));
            image.srgb8[at + 1] = srgb_byte(srgb, float(c.y));
            image.srgb8[at + 2] = srgb_byte(srgb, float(c.z));
        } else {
            image.pixels[at] = float(c.x), image.pixels[at + 1] = float(c.y), image.pixels[at + 2] = float(c.z);
        }
    };

    const int tiles_x = (image.width + kTile - 1) / kTile, tiles_y = (image.height + kTile - 1) / kTile;
    const int tiles = tiles_x * tiles_y;
    tbb::enumerable_thread_specific<ThreadState> states;
    std::mutex progress_mutex;
    int tiles_done = 0;

    // `traced` false: the pixel's tile misses the whole scene (tile_cull.cpp)
    // and every ray is taken as a miss without tracing. The pixel gets what
    // tracing would give (the same sums), so its value never depends on
    // which tile it falls in (crops move tile borders).
    auto render_pixel = [&](int x, int y, ThreadState& ts, bool traced) {
        glm::dvec3 o, d;
        if (options.aov != Aov::None) {  // AOVs: one ray through the pixel centre
            float* out = &image.at(x - region[0], y - region[1], 0);
            ++ts.rays.primary;
            const std::uint64_t spans_before = ts.scratch.counters.spans_found;
            TraceHit hit;
            bool found = false;
            if (traced) {
                camera.ray(x + 0.5, y + 0.5, o, d);
                found = tracer.intersect(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, hit, ts.scratch);
            }
            if (options.aov == Aov::Depth) {
                out[0] = found ? float(hit.t) : std::numeric_limits<float>::infinity();
            } else if (options.aov == Aov::Normal) {
                const glm::dvec3 n = found ? tracer.normal(hit, o + hit.t * d) : glm::dvec3(0.0);
                out[0] = float(n.x), out[1] = float(n.y), out[2] = float(n.z);
            } else {
                out[0] = float(ts.scratch.counters.spans_found - spans_before);
            }
            return;
        }
        auto sample = [&](double px, double py) {
            ++ts.rays.primary;
            if (!traced) return scene.background;
            camera.ray_unnormalised(px, py, o, d);
            return shader.radiance(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, 0, ts);
        };
        glm::dvec3 sum(0.0);
        if (spp == 1) {  // the pixel centre: no jitter, no generator to seed
            sum = sample(x + 0.5, y + 0.5);
        } else {
            std::uint64_t rng = options.seed * 0x9E3779B97F4A7C15ull ^ (std::uint64_t(y) << 32 | std::uint32_t(x));
            splitmix64(rng);
            for (int i = 0; i < spp; ++i) {
                const glm::dvec2 s = sample_offset(i, spp, rng);
                sum += sample(x + s.x, y + s.y);
            }
            sum /= double(spp);
        }
        store(x, y, sum);
    };

    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
            // Denormals only slow the quartic solvers down; every thread uses
            // the same mode, so results stay thread-count independent.
            // The caller's thread may run tiles too: restore its mode after.
            const unsigned saved_ftz = _MM_GET_FLUSH_ZERO_MODE(), saved_daz = _MM_GET_DENORMALS_ZERO_MODE();
            _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
            _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
            ThreadState& ts = states.local();
            for (int tile = r.begin(); tile != r.end(); ++tile) {
                const int tx0 = region[0] + (tile % tiles_x) * kTile, ty0 = region[1] + (tile / tiles_x) * kTile;
                const int tx1 = std::min(tx0 + kTile, region[2]), ty1 = std::min(ty0 + kTile, region[3]);
                glm::dvec3 co[4], cd[4];  // the tile's corner rays, in order round it
                camera.ray(tx0, ty0, co[0], cd[0]);
                camera.ray(tx1, ty0, co[1], cd[1]);
                camera.ray(tx1, ty1, co[2], cd[2]);
                camera.ray(tx0, ty1, co[3], cd[3]);
                const bool traced = !tracer.misses_all(co, cd);
                for (int y = ty0; y < ty1; ++y)
                    for (int x = tx0; x < tx1; ++x) render_pixel(x, y, ts, traced);
                if (progress) {
                    std::lock_guard<std::mutex> lock(progress_mutex);
                    progress(double(++tiles_done) / tiles);
                }
            }
            _MM_SET_FLUSH_ZERO_MODE(saved_ftz);
            _MM_SET_DENORMALS_ZERO_MODE(saved_daz);
        });
    });

    if (stats) {
        *stats = RenderStats{};
        for (const ThreadState& ts : states) {
            stats->primary_rays += ts.rays.primary;
            stats->shadow_rays += ts.rays.shadow;
            stats->reflect_rays += ts.rays.reflect;
            stats->union_ops += ts.scratch.counters.union_ops;
            stats->difference_ops += ts.scratch.counters.difference_ops;
            stats->intersection_ops += ts.scratch.counters.intersection_ops;
            stats->interval_tests += ts.scratch.counters.interval_tests;
        }
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return image;
}

}  // namespace kerf::render
