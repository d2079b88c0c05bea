// render(): the tracer, shader and camera built once, then every pixel of
// the region through for_each_tile (tiles.hpp): colour from its samples
// (sampler.hpp) or an AOV (aov.cpp), stored by the PixelStore. Every pixel
// depends only on (scene, options, seed, its full-image coordinates), so
// the thread count and a crop never change a pixel's value (README.md).
#include "render/render.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>


#include "render/adaptive.hpp"
#include "render/aov.hpp"
#include "render/camera.hpp"
#include "render/corner_probes.hpp"
#include "render/edge_coverage.hpp"
#include "render/ghosts.hpp"
#include "render/integrator_path.hpp"
#include "render/ground.hpp"
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
    // Coverage: the samples of the pixel being shaded that hit a solid (a
    // sample seeing a ghost over the background counts the ghost's
    // opacity). A pixel is shaded start to end on one thread, so a
    // thread-local count, reset per pixel, needs no change to the sample
    // paths below.
    static thread_local double hits = 0;
    static thread_local double last_cover = 0;  // what the last sample added to `hits`
    auto put = [&](int x, int y, const glm::dvec3& c, int samples) {
        if (alpha) store.color_alpha(x, y, c, hits / samples, shader.miss(), options.alpha == Alpha::Premultiplied);
        else store.color(x, y, c);
        hits = 0;
    };
    tbb::enumerable_thread_specific<ThreadState> states;

    // The colour seen along (o, d); `surface` as Shader::radiance.
    auto trace = [&](const glm::dvec3& o, const glm::dvec3& d, ThreadState& ts, std::uint32_t* surface) {
        const TraceRay ray{o, d, 0, std::numeric_limits<double>::infinity()};
        auto one = [&](std::uint32_t* id) {
            if (path) {
                std::uint32_t seen = 0;
                const glm::dvec3 c = path->radiance(o, d, ts, &seen);
                if (id) *id = seen;
                // The studio ground is a shadow catcher, not a surface that
                // scatters: where a camera ray misses the solid, the shader
                // draws it (elsewhere the same miss colour as the path's).
                if (seen == 0) return shader.missed(ray, ts);
                return c;
            }
            return shader.radiance(ray, 0, ts, id);
        };
        if (!alpha) {
            const glm::dvec3 c = one(surface);
            return ghosts ? ghosts->over(ray, c, ts, nullptr, surface) : c;
        }
        std::uint32_t id = 0;
        glm::dvec3 c = one(&id);
        if (surface) *surface = id;
        double ghost = 0;
        if (ghosts) c = ghosts->over(ray, c, ts, &ghost, surface);
        last_cover = id != 0 ? 1.0 : ghost;
        hits += last_cover;
        return c;
    };
    // One sample through (px, py); `surface` as Shader::radiance.
    auto sample = [&](double px, double py, ThreadState& ts, bool traced, std::uint32_t* surface) {
        ++ts.rays.primary;
        glm::dvec3 o, d;
        if (!traced || !camera.ray_unnormalised(px, py, o, d)) {  // culled, or outside a fisheye's circle
            if (surface) *surface = 0;
            return shader.miss();
        }
        return trace(o, d, ts, surface);
    };
    // Only the surface a sample through (px, py) would see (Shader::surface).
    auto surface_sample = [&](double px, double py, ThreadState& ts, bool traced) -> std::uint32_t {
        ++ts.rays.primary;
        glm::dvec3 o, d;
        if (!traced || !camera.ray_unnormalised(px, py, o, d)) return 0;
        return shader.surface(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, ts);
    };
    // Depth of field: one sample through (px, py) from lens point `lens`.
    auto lens_sample = [&](double px, double py, glm::dvec2 lens, ThreadState& ts, bool traced) {
        ++ts.rays.primary;
        if (!traced) return shader.miss();
        glm::dvec3 o, d;
        camera.ray_through_lens(px, py, lens, o, d);
        return trace(o, d, ts, nullptr);
    };
    // The mean of `pattern`'s samples in pixel (x, y).
    auto samples_mean = [&](const SamplePattern& pattern, int x, int y, ThreadState& ts, bool traced) {
        const int n = pattern.count();
        if (n == 1) return sample(x + 0.5, y + 0.5, ts, traced, nullptr);  // the centre: no jitter, no generator
        std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
        glm::dvec3 sum(0.0);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 s = pattern.offset(i, rng);
            sum += sample(x + s.x, y + s.y, ts, traced, nullptr);
        }
        return sum / double(n);
    };

    // `progress` for a pass that covers the fractions from..to of the render.
    auto part = [&](double from, double to) -> std::function<void(double)> {
        if (!progress) return {};
        return [&progress, from, to](double f) { progress(from + (to - from) * f); };
    };
    bool complete = true;
    int paths_done = 0;  // the path integrator: paths per pixel in the image
    if (aov != Aov::None) {
        complete &= for_each_tile(arena, region, camera, tracer, shadow, states, progress, stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
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
        complete &= for_each_tile(arena, region, camera, tracer, shadow, states, progress, stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
            hits = 0;
            std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
            std::uint64_t lens_rng = rng ^ 0x6C656E73u;  // "lens"
            const int shift = int(splitmix64(lens_rng) % std::uint64_t(n));
            glm::dvec3 sum(0.0);
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 s = blur.offset(i, rng);
                const glm::dvec2 l = blur.offset(int((std::int64_t(i) * blur.step() + shift) % n), lens_rng);
                sum += lens_sample(x + s.x, y + s.y, l, ts, traced);
            }
            put(x, y, sum / double(n), n);
        });
        // Not in passes: every sample pairs a pixel stratum with a lens one.
        if (path) {
            paths_done = n;
            if (complete && !cancelled() && options.on_pass) options.on_pass(image, n);
        }
    } else if (options.adaptive && !options.preview && !path) {
        // Centres first (about a quarter of the time), then the refinement.
        CentreSamples centres(region, options.width, options.height);
        const SamplePattern refine(options.aa_samples);
        const int threshold = int(std::lround(options.aa_threshold * 255));
        const std::array<int, 4> area = centres.area();
        complete &= for_each_tile(arena, area, camera, tracer, shadow, states, part(0, 0.25), stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
            std::uint32_t surface;
            ts.on_ground = false;
            const glm::dvec3 c = sample(x + 0.5, y + 0.5, ts, traced, &surface);
            centres.set(x, y, ts.on_ground ? shader.miss() : c, surface, ts.on_ground);
            if (x >= region[0] && x < region[2] && y >= region[1] && y < region[3]) put(x, y, c, 1);
            hits = 0;
        });
        // Only candidates are written again; the rest keep their centre.
        static thread_local CornerProbes probes;
        const std::uint64_t generation = CornerProbes::next_generation();
        // What a probe looks like to the first pass: the ground as a miss.
        auto alike = [&](const CornerProbe& a, const CornerProbe& b) {
            return centres.alike(a.on_ground ? shader.miss() : a.color, a.surface,
                                 b.on_ground ? shader.miss() : b.color, b.surface, threshold);
        };
        // A sample through (px, py) with what the first pass compares: its
        // look, surface and whether it saw the ground.
        auto probe_at = [&](double px, double py, ThreadState& ts, bool traced) {
            CornerProbe p;
            ts.on_ground = false;
            p.color = sample(px, py, ts, traced, &p.surface);
            p.on_ground = ts.on_ground;
            return p;
        };
        // The corner (cx, cy) of the current tile, traced once.
        auto corner = [&](int cx, int cy, ThreadState& ts, bool traced) -> CornerProbe& {
            CornerProbe& p = probes.at(cx, cy);
            if (!p.traced) {
                last_cover = 0;  // a culled sample traces nothing and covers nothing
                p = probe_at(cx, cy, ts, traced);
                p.cover = last_cover;
                p.traced = true;
            } else {
                hits += alpha ? p.cover : 0.0;
            }
            return p;
        };
        // The centre sample's colour. An 8-bit image stores it to 8 bits
        // anyway: decoded from its look, not traced again (a mean of 5
        // moves by at most a tenth of a code). Float images trace it again.
        auto centre_color = [&](int x, int y, ThreadState& ts, bool traced) {
            const std::optional<glm::dvec3> kept = options.srgb8 && !alpha ? centres.color(x, y) : std::nullopt;
            return kept ? *kept : sample(x + 0.5, y + 0.5, ts, traced, nullptr);
        };
        // A straight edge located to 1/2^steps of a side: 1/16 for the
        // default 16 samples, as fine as their 4 × 4 strata.
        const int steps = std::max(1, int(std::ceil(std::log2(double(options.aa_samples)))));
        // Which of two probes p and q of different looks a sample through
        // (px, py) looks like: 0 (p), 1 (q) or -1 (both or neither: a third
        // surface, a gradient). Between two surfaces the surface alone
        // decides, and the sample is not shaded (`color` stays empty);
        // between two looks of one surface (a shadow's edge) or under
        // ghosts, the look, and `color` gets the sample's.
        auto like = [&](double px, double py, const CornerProbe& p, const CornerProbe& q, ThreadState& ts, bool traced,
                        std::optional<glm::dvec3>& color) -> int {
            if (p.surface != q.surface && !ghosts) {
                const std::uint32_t seen = surface_sample(px, py, ts, traced);
                return seen == p.surface ? 0 : seen == q.surface ? 1 : -1;
            }
            const CornerProbe probe = probe_at(px, py, ts, traced);
            const bool like_p = alike(probe, p), like_q = alike(probe, q);
            if (like_p == like_q) return -1;
            color = probe.color;
            return like_q;
        };
        // Where the look changes along the side from corner (cx, cy) to the
        // next one right (or down): bisection.
        auto side = [&](int cx, int cy, bool vertical, ThreadState& ts, bool traced) -> const SideProbe& {
            SideProbe& s = probes.side(cx, cy, vertical);
            if (s.traced) return s;
            const CornerProbe &p = probes.at(cx, cy), &q = probes.at(cx + !vertical, cy + vertical);
            s = SideProbe{};
            s.traced = s.clean = true;
            s.sum[0] = s.sum[1] = glm::dvec3(0.0);
            double lo = 0, hi = 1;
            for (int i = 0; i < steps; ++i) {
                const double m = (lo + hi) / 2;
                std::optional<glm::dvec3> color;
                const int seen = like(cx + (vertical ? 0 : m), cy + (vertical ? m : 0), p, q, ts, traced, color);
                if (seen < 0) {
                    s.clean = false;
                    break;
                }
                (seen == 0 ? lo : hi) = m;
                if (color) s.sum[seen] += *color, ++s.count[seen];
            }
            s.at = (lo + hi) / 2;
            return s;
        };
        auto straight_edge = [&](int x, int y, const std::array<const CornerProbe*, 4>& k, ThreadState& ts,
                                 bool traced) -> std::optional<glm::dvec3> {
            std::array<bool, 4> a{};  // like corner 0 (class A), else like corner b (class B)
            int b = -1;
            for (int i = 0; i < 4; ++i) {
                a[i] = alike(*k[i], *k[0]);
                if (a[i]) continue;
                if (b < 0) b = i;
                else if (!alike(*k[i], *k[b])) return std::nullopt;  // a third look
            }
            if (b < 0) return std::nullopt;  // the centre differs from all four corners: a thin feature
            int changes = 0;
            for (int i = 0; i < 4; ++i) changes += a[i] != a[(i + 1) % 4];
            if (changes != 2) return std::nullopt;  // two edges, or a corner of the solid
            auto like_centre = [&](const CornerProbe& p) {
                return centres.looks_alike(x, y, p.on_ground ? shader.miss() : p.color, p.surface, threshold);
            };
            const bool centre_a = like_centre(*k[0]);
            if (centre_a == like_centre(*k[b])) return std::nullopt;
            // Each class's colour: the mean of its samples (corners, centre, sides).
            glm::dvec3 sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};  // class A, class B
            int count[2] = {0, 0};
            for (int i = 0; i < 4; ++i) sum[!a[i]] += k[i]->color, ++count[!a[i]];
            sum[!centre_a] += centre_color(x, y, ts, traced), ++count[!centre_a];
            std::array<glm::dvec2, 4> cross{};
            int crossed[2], n = 0;
            for (int i = 0; i < 4; ++i) {
                if (a[i] == a[(i + 1) % 4]) continue;
                // Side i of the pixel runs from corner i to i + 1; the probes
                // run left to right and top to bottom: sides 2 and 3 backwards.
                static constexpr int dx[4] = {0, 1, 0, 0}, dy[4] = {0, 0, 1, 0};
                const SideProbe& s = side(x + dx[i], y + dy[i], i % 2 == 1, ts, traced);
                if (!s.clean) return std::nullopt;
                const bool backwards = i >= 2;
                // The probe's first corner is pixel corner i, or i + 1 when backwards.
                const bool first_a = a[backwards ? (i + 1) % 4 : i];
                sum[!first_a] += s.sum[0], count[!first_a] += s.count[0];
                sum[first_a] += s.sum[1], count[first_a] += s.count[1];
                cross[i] = on_side(i, backwards ? 1 - s.at : s.at);
                crossed[n++] = i;
            }
            // The centre must lie on its own class's side of the line (or
            // within the crossings' precision of it): else the edge bends.
            // (Corner 0 is of class A.)
            const double d = side_distance(cross[crossed[0]], cross[crossed[1]], pixel_corner(0), {0.5, 0.5});
            const double tolerance = std::ldexp(1.0, -steps);
            if (centre_a ? d < -tolerance : d > tolerance) return std::nullopt;
            // Two adjacent sides cut off the corner between them. A corner
            // of the solid there (two edges meeting inside the pixel) keeps
            // that corner's look on the far side of the line, beyond what
            // the centre shows: one more sample, 2/2^steps past the middle
            // of the line, away from that corner.
            if ((crossed[1] - crossed[0]) % 2 == 1) {
                const int odd = crossed[1] - crossed[0] == 1 ? crossed[1] : 0, rest = (odd + 2) % 4;
                const glm::dvec2 m = (cross[crossed[0]] + cross[crossed[1]]) / 2.0;
                const glm::dvec2 at = m + 2 * tolerance * glm::normalize(m - pixel_corner(odd));
                std::optional<glm::dvec3> color;
                if (like(x + at.x, y + at.y, *k[rest], *k[odd], ts, traced, color) != 0) return std::nullopt;
                if (color) sum[!a[rest]] += *color, ++count[!a[rest]];
            }
            const double area = covered_area(a, cross);
            return area * (sum[0] / double(count[0])) + (1 - area) * (sum[1] / double(count[1]));
        };
        complete &= for_each_tile(arena, region, camera, tracer, shadow, states, part(0.25, 1), stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
            hits = 0;
            if (!centres.needs_more(x, y, threshold)) return;
            // Probes at the 4 corners first: a straight edge that crosses the
            // pixel always separates its corners, so a candidate whose
            // corners all look like its centre (next to an edge but wholly
            // on one side, about half of them) stops there with their mean.
            bool same = true;
            glm::dvec3 sum(0.0);
            // A corner is shared by up to 4 candidates: traced once per tile
            // (corner_probes.hpp), the same value whichever pixel asks.
            probes.enter(region[0] + (x - region[0]) / kTile * kTile, region[1] + (y - region[1]) / kTile * kTile, generation);
            std::array<const CornerProbe*, 4> round{};  // the corners in order round the pixel
            for (int i = 0; i < 4; ++i) {
                const CornerProbe& p = corner(x + (i & 1), y + (i >> 1), ts, traced);
                round[i < 2 ? i : 5 - i] = &p;
                same = same && centres.looks_alike(x, y, p.on_ground ? shader.miss() : p.color, p.surface, threshold);
                sum += p.color;
            }
            if (same) {
                put(x, y, (centre_color(x, y, ts, traced) + sum) / 5.0, 5);
                return;
            }
            // One straight edge across the pixel: located on the sides it
            // crosses, its share of the pixel exact for that line. Not with
            // --alpha, whose coverage counts samples.
            ts.refining = true;
            const std::optional<glm::dvec3> edge = alpha ? std::nullopt : straight_edge(x, y, round, ts, traced);
            ts.refining = false;
            if (edge) {
                ++ts.edge_pixels;
                put(x, y, *edge, 1);
                return;
            }
            ++ts.refined_pixels;
            hits = 0;
            ts.refining = true;
            put(x, y, samples_mean(refine, x, y, ts, traced), refine.count());
            ts.refining = false;
        });
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
            complete &= for_each_tile(arena, region, camera, tracer, shadow, states, part(double(done) / n, double(to) / n), stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
                const std::size_t at = passes ? std::size_t(y - region[1]) * w + (x - region[0]) : 0;
                hits = hit_counts.empty() ? 0 : hit_counts[at];
                if (n == 1) {
                    put(x, y, sample(x + 0.5, y + 0.5, ts, traced, nullptr), 1);  // the centre, as samples_mean
                    return;
                }
                std::uint64_t rng = SamplePattern::pixel_rng(options.seed, x, y);
                SamplePattern::skip(rng, done);
                glm::dvec3 sum = passes ? sums[at] : glm::dvec3(0.0);
                for (int j = done; j < to; ++j) {
                    const glm::dvec2 s = samples.offset(int(std::int64_t(j) * samples.step() % n), rng);
                    sum += sample(x + s.x, y + s.y, ts, traced, nullptr);
                }
                if (passes) sums[at] = sum;
                if (!hit_counts.empty()) hit_counts[at] = hits;
                put(x, y, sum / double(to), to);
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
        // The plain render (1 spp, no alpha, no ghosts): the pixel centre's
        // ray straight to the shader and the store, the same calls `sample`
        // and `put` make without their per-pixel branches and counters.
        complete &= for_each_tile(arena, region, camera, tracer, shadow, states, progress, stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
            ++ts.rays.primary;
            glm::dvec3 o, d;
            if (!traced || !camera.ray_unnormalised(x + 0.5, y + 0.5, o, d)) {
                store.color(x, y, shader.miss());
                return;
            }
            store.color(x, y, shader.radiance(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, 0, ts));
        });
    } else {
        complete &= for_each_tile(arena, region, camera, tracer, shadow, states, progress, stack_need, options.cancel, [&](int x, int y, ThreadState& ts, bool traced) {
            hits = 0;
            put(x, y, samples_mean(samples, x, y, ts, traced), samples.count());
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
