// render(): the tracer, shader and camera built once, then every pixel of
// the region through the tiles' passes (tiles.hpp): colour from its samples
// (pixel_sampler.hpp; adaptive anti-aliasing in adaptive_aa.cpp) or an AOV
// (aov.cpp), stored by the PixelStore. Every pixel
// depends only on (scene, options, seed, its full-image coordinates), so
// the thread count and a crop never change a pixel's value (README.md).
#include "render/render.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "render/adaptive_aa.hpp"
#include "render/aov.hpp"
#include "render/camera.hpp"
#include "render/ghosts.hpp"
#include "render/integrator_path.hpp"
#include "render/ground.hpp"
#include "render/pixel_sampler.hpp"
#include "render/pixel_store.hpp"
#include "render/sampler.hpp"
#include "render/shading.hpp"
#include "render/stats.hpp"
#include "render/tiles.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

namespace {

void check_options(const RenderOptions& o) {
    if (o.width < 1 || o.height < 1) throw std::invalid_argument("image size must be at least 1×1");
    if (o.spp < 1) throw std::invalid_argument("samples per pixel must be at least 1");
    if (o.adaptive && (o.aa_samples < 2 || !(o.aa_threshold >= 0 && o.aa_threshold <= 1)))
        throw std::invalid_argument("adaptive anti-aliasing needs at least 2 samples and a threshold from 0 to 1");
    if (o.threads < 0) throw std::invalid_argument("thread count must not be negative");
    if (o.max_path_depth < 0) throw std::invalid_argument("path depth must not be negative");
    if (!(o.time_limit >= 0)) throw std::invalid_argument("time limit must not be negative");
    if (o.crop) {
        const auto& c = *o.crop;
        if (c[0] < 0 || c[1] < 0 || c[2] > o.width || c[3] > o.height || c[0] >= c[2] || c[1] >= c[3])
            throw std::invalid_argument("crop rectangle must lie inside the image and not be empty");
    }
}

Image render_tiles(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats,
                   const std::function<void(double)>& progress, std::size_t stack_need) {
    const auto start = std::chrono::steady_clock::now();
    // Embree builds its BVHs with TBB: inside the arena, so `threads` bounds
    // the build as well as the rendering.
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    std::optional<CsgTracer> built;
    arena.execute([&] { built.emplace(scene, !options.double_precision); });
    const CsgTracer& tracer = *built;
    auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };
    if (cancelled()) throw RenderCancelled();
    if (progress) progress(0.0);  // the BVHs are built; tracing starts (render.hpp)
    const SamplePattern samples(options.preview ? 1 : options.spp);
    const CameraModel camera(scene.camera, options.width, options.height);

    const std::array<int, 4> region = options.crop ? *options.crop
                                                   : std::array<int, 4>{0, 0, options.width, options.height};
    const Aov aov = options.aov;
    Image image;
    const bool alpha = options.alpha != Alpha::None && aov == Aov::None;
    // The ground is neither in the AOVs (they see the solid) nor in an
    // --alpha image (transparent, as the background it stands for).
    const Shader shader(scene, tracer, options.preview ? 0 : options.max_reflect_depth, !alpha);
    csg::Aabb shadow = alpha || aov != Aov::None ? csg::Aabb{} : ground_shadow_box(scene);
    // The `%` and `#` ghosts over the colour (AOVs see the solid only);
    // tiles where they show are traced like those the ground's shadow needs.
    std::optional<GhostLayers> ghosts;
    if (!scene.ghosts.empty() && aov == Aov::None) {
        arena.execute([&] { ghosts.emplace(scene, tracer, !options.double_precision); });
        shadow.extend(ghosts->bounds());
    }
    // The path tracer, when asked for (the preview stays Whitted's quick look).
    std::optional<PathTracer> path;
    if (options.integrator == Integrator::Path && !options.preview)
        path.emplace(scene, tracer, options.max_path_depth, options.seed, options.path_lighting);
    PixelStore store(image, region, alpha ? 4 : aov_channels(aov), aov_content(aov), options.srgb8 && aov == Aov::None);
    store.expect(shader.miss());
    const PixelSampler sampler(camera, shader, ghosts ? &*ghosts : nullptr, path ? &*path : nullptr, store,
                               alpha ? options.alpha : Alpha::None, options.seed);
    tbb::enumerable_thread_specific<ThreadState> states;
    const TilePasses tiles{arena, camera, tracer, shadow, states, stack_need, options.cancel};

    bool complete = true;
    int paths_done = 0;  // the path integrator: paths per pixel in the image
    if (aov != Aov::None) {
        complete &= tiles.run(region, progress, [&](int x, int y, ThreadState& ts, bool traced) {
            aov_pixel(aov, camera, tracer, x, y, ts, traced, store.values(x, y));
        });
    } else if (camera.has_lens() && !options.preview) {
        // Depth of field: every pixel is blurred somewhere, so no adaptive
        // pass; max(blur_samples, spp) samples, stratified over the pixel
        // (the `--spp` pattern and stream, so the plane of focus gets the
        // pinhole's pixels) and over the lens (the same pattern from a
        // stream of its own, strata paired by a per-pixel shifted golden step).
        const SamplePattern blur(std::max(int(scene.camera.blur_samples), options.spp));
        const int n = blur.count();
        complete &= tiles.run(region, progress, [&](int x, int y, ThreadState& ts, bool traced) {
            PixelSampler::set_covered(0);
            std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
            std::uint64_t lens_rng = rng ^ 0x6C656E73u;  // "lens"
            const int shift = int(splitmix64(lens_rng) % std::uint64_t(n));
            glm::dvec3 sum(0.0);
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 s = blur.offset(i, rng);
                const glm::dvec2 l = blur.offset(int((std::int64_t(i) * blur.step() + shift) % n), lens_rng);
                sum += sampler.lens_sample(x + s.x, y + s.y, l, ts, traced);
            }
            sampler.put(x, y, sum / double(n), n);
        });
        // Not in passes: every sample pairs a pixel stratum with a lens one.
        if (path) {
            paths_done = n;
            if (complete && !cancelled() && options.on_pass) options.on_pass(image, n);
        }
    } else if (options.adaptive && !options.preview && !path) {
        complete &= render_adaptive(tiles, sampler, options, region, progress);
    } else if (path) {
        // Paths in passes (RenderOptions::on_pass): each pixel's running sum
        // and hit count are kept between passes and continued in the same
        // order, so the last pass ends with the very sums one pass would.
        // Samples are taken in the order i·step mod n, so the strata of any
        // first few spread over the pixel instead of filling its top row.
        const int n = samples.count(), w = region[2] - region[0];
        const bool passes = bool(options.on_pass) || options.time_limit > 0;
        std::vector<glm::dvec3> sums(passes ? std::size_t(w) * (region[3] - region[1]) : 0);
        std::vector<double> hit_counts(passes && alpha ? sums.size() : 0);
        int done = 0;
        while (done < n && complete) {
            const int to = passes ? std::min(n, std::max(1, 2 * done)) : n;
            complete &= tiles.run(region, progress_part(progress, double(done) / n, double(to) / n), [&](int x, int y, ThreadState& ts, bool traced) {
                const std::size_t at = passes ? std::size_t(y - region[1]) * w + (x - region[0]) : 0;
                PixelSampler::set_covered(hit_counts.empty() ? 0 : hit_counts[at]);
                if (n == 1) {
                    sampler.put(x, y, sampler.sample(x + 0.5, y + 0.5, ts, traced, nullptr), 1);  // the centre, as PixelSampler::mean
                    return;
                }
                std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
                SamplePattern::skip(rng, done);
                glm::dvec3 sum = passes ? sums[at] : glm::dvec3(0.0);
                for (int j = done; j < to; ++j) {
                    const glm::dvec2 s = samples.offset(int(std::int64_t(j) * samples.step() % n), rng);
                    sum += sampler.sample(x + s.x, y + s.y, ts, traced, nullptr);
                }
                if (passes) sums[at] = sum;
                if (!hit_counts.empty()) hit_counts[at] = PixelSampler::covered();
                sampler.put(x, y, sum / double(to), to);
            });
            done = to;
            if (!complete || cancelled()) break;
            if (options.on_pass) options.on_pass(image, done);
            if (options.time_limit > 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= options.time_limit)
                break;
        }
        paths_done = done;
    } else if (samples.count() == 1 && !alpha && !ghosts) {
        // The plain render (1 spp, no alpha, no ghosts): the pixel centres
        // straight to the store, the same calls `sample` and `put` make
        // without their per-pixel branches and counters, a block's row at a
        // time (PixelSampler::centre_row: traced, then shaded). A culled
        // block's rows are filled whole.
        static_assert(kBlock <= PixelSampler::kMaxRow);
        const glm::dvec3 miss = shader.miss();
        complete &= tiles.run_rows(region, progress, [&](int x0, int x1, int y, ThreadState& ts, bool traced) {
            if (!traced) {
                ts.rays.primary += std::uint64_t(x1 - x0);
                return store.fill(x0, x1, y, miss);
            }
            glm::dvec3 colour[kBlock];
            sampler.centre_row(x0, x1, y, ts, colour);
            for (int i = 0; i < x1 - x0; ++i) store.color(x0 + i, y, colour[i]);
        });
    } else {
        complete &= tiles.run(region, progress, [&](int x, int y, ThreadState& ts, bool traced) {
            PixelSampler::set_covered(0);
            sampler.put(x, y, sampler.mean(samples, x, y, ts, traced), samples.count());
        });
    }
    if (cancelled()) throw RenderCancelled();
    if (!complete)
        throw std::runtime_error("a render thread has less stack than this scene's CSG tree needs (" +
                                 std::to_string(stack_need >> 20) + " MiB): TBB's threads were started with a smaller one");

    if (stats) {
        *stats = sum_stats(states, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        stats->paths_per_pixel = paths_done;
    }
    return image;
}

}  // namespace

Image render(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats,
             std::function<void(double)> progress) {
    check_options(options);
    // The tracer recurses once per tree level (tracer/stack_depth.hpp):
    // refuse what no stack is sized for, and give every thread that traces
    // the stack this tree needs rather than let a deep one overflow it.
    Image image;
    // The deepest of the solid's and the ghosts' trees sets the stack.
    const csg::Scene* deepest = &scene;
    for (const csg::Scene& ghost : scene.ghosts)
        if (tree_depth(ghost) > tree_depth(*deepest)) deepest = &ghost;
    with_tracer_stack(*deepest, "renders", [&](std::size_t need) { image = render_tiles(scene, options, stats, progress, need); });
    return image;
}

}  // namespace kerf::render
