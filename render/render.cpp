// render(): the tracer, shader and camera built once, then every pixel of
// the region through for_each_tile (tiles.hpp): colour from its samples
// (sampler.hpp) or an AOV (aov.cpp), stored by the PixelStore. Every pixel
// depends only on (scene, options, seed, its full-image coordinates), so
// the thread count and a crop never change a pixel's value (README.md).
#include "render/render.hpp"

#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <tbb/global_control.h>

#include "render/aov.hpp"
#include "render/camera.hpp"
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
    if (o.threads < 0) throw std::invalid_argument("thread count must not be negative");
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
    const SamplePattern samples(options.preview ? 1 : options.spp);
    const Shader shader(scene, tracer, options.preview ? 0 : options.max_reflect_depth);
    const CameraModel camera(scene.camera, options.width, options.height);

    const std::array<int, 4> region = options.crop ? *options.crop
                                                   : std::array<int, 4>{0, 0, options.width, options.height};
    const Aov aov = options.aov;
    Image image;
    PixelStore store(image, region, aov_channels(aov), aov_content(aov), options.srgb8 && aov == Aov::None);
    tbb::enumerable_thread_specific<ThreadState> states;

    const bool complete = for_each_tile(arena, region, camera, tracer, states, progress, stack_need,
                                        [&](int x, int y, ThreadState& ts, bool traced) {
        if (aov != Aov::None) {
            aov_pixel(aov, camera, tracer, x, y, ts, traced, store.values(x, y));
            return;
        }
        auto sample = [&](double px, double py) {
            ++ts.rays.primary;
            if (!traced) return scene.background;
            glm::dvec3 o, d;
            camera.ray_unnormalised(px, py, o, d);
            return shader.radiance(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, 0, ts);
        };
        glm::dvec3 sum(0.0);
        const int n = samples.count();
        if (n == 1) {  // the pixel centre: no jitter, no generator to seed
            sum = sample(x + 0.5, y + 0.5);
        } else {
            std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 s = samples.offset(i, rng);
                sum += sample(x + s.x, y + s.y);
            }
            sum /= double(n);
        }
        store.color(x, y, sum);
    });
    if (!complete)
        throw std::runtime_error("a render thread has less stack than this scene's CSG tree needs (" +
                                 std::to_string(stack_need >> 20) + " MiB): TBB's threads were started with a smaller one");

    if (stats) *stats = sum_stats(states, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return image;
}

}  // namespace

Image render(const csg::Scene& scene, const RenderOptions& options, RenderStats* stats,
             std::function<void(double)> progress) {
    check_options(options);
    // The tracer recurses once per tree level (tracer/stack_depth.hpp):
    // refuse what no stack is sized for, and give every thread that traces
    // the stack this tree needs rather than let a deep one overflow it.
    const std::uint32_t depth = tree_depth(scene);
    if (depth > csg::kMaxDepth)
        throw std::runtime_error("the CSG tree is " + std::to_string(depth) + " levels deep; kerf renders trees up to " +
                                 std::to_string(csg::kMaxDepth) + " levels deep");
    const std::size_t need = stack_needed(depth);
    // TBB's workers are started with this stack (when this is the process's
    // first render; otherwise a worker that has too little traces nothing
    // and the render fails with a message).
    const std::size_t worker_stack = std::max(need + kStackBase, tbb::global_control::active_value(tbb::global_control::thread_stack_size));
    tbb::global_control stack_size(tbb::global_control::thread_stack_size, worker_stack);
    if (stack_left() >= need) return render_tiles(scene, options, stats, progress, need);
    Image image;
    run_with_stack(need + kStackBase, [&] { image = render_tiles(scene, options, stats, progress, need); });
    return image;
}

}  // namespace kerf::render
