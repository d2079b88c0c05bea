// One render's samples: the colour a ray through a point of the image sees
// (the camera, the Whitted shader or the path tracer, the ghosts over
// them), the mean of a pixel's sample pattern, and the pixel stored with
// its --alpha coverage. Shared by every pass of render.cpp and by adaptive
// anti-aliasing (adaptive_aa.cpp).
#pragma once
#include <cassert>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/ghosts.hpp"
#include "render/integrator_path.hpp"
#include "render/pixel_store.hpp"
#include "render/render.hpp"
#include "render/sampler.hpp"
#include "render/shading.hpp"

namespace kerf::render {

class PixelSampler {
public:
    // `ghosts`, `path`: null when the render has none. `alpha`: None for
    // colour without coverage (and for AOVs).
    PixelSampler(const CameraModel& camera, const Shader& shader, const GhostLayers* ghosts, const PathTracer* path,
                 PixelStore& store, Alpha alpha, std::uint64_t seed)
        : camera_(camera), shader_(shader), ghosts_(ghosts), path_(path), store_(store), alpha_(alpha), seed_(seed),
          plain_(!ghosts && !path && alpha == Alpha::None) {}

    bool alpha() const { return alpha_ != Alpha::None; }
    bool ghosts() const { return ghosts_ != nullptr; }
    const glm::dvec3& miss() const { return shader_.miss(); }
    std::uint64_t seed() const { return seed_; }

    // One sample through (px, py); `surface` as Shader::radiance. Not
    // `traced` (a culled tile): the miss colour.
    glm::dvec3 sample(double px, double py, ThreadState& ts, bool traced, std::uint32_t* surface = nullptr) const {
        ++ts.rays.primary;
        glm::dvec3 o, d;
        if (!traced || !camera_.ray_unnormalised(px, py, o, d)) {  // culled, or outside a fisheye's circle
            if (surface) *surface = 0;
            return shader_.miss();
        }
        // The Whitted shader alone (what trace() comes to without ghosts,
        // paths or coverage): called here, not through trace()'s branches
        // (~40 instructions a sample, 1.3 % of holes_40's default render).
        if (plain_) return shader_.radiance(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, 0, ts, surface);
        return trace(o, d, ts, surface);
    }
    // Whether a sample is the shader's radiance alone (no ghosts, no path
    // tracer, no coverage): centre_row() then applies.
    bool plain() const { return plain_; }
    static constexpr int kMaxRow = 8;  // centre_row's pixels at most (a block's row)
    // The centres of pixels [x0, x1) of row y, traced, of a plain sampler:
    // colour[i] (and surface[i] and ground[i], ThreadState::on_ground, when
    // `surface` is given) as sample(x + 0.5, y + 0.5, ts, true, surface)
    // gives them one by one, but the row's rays traced first (their first
    // leaf solved ahead, CsgTracer::solve_ahead), then shaded, so each
    // ray's chains of divisions and square roots overlap its neighbours'
    // instead of stalling it (docs/performance.md, "Grooves, fourth
    // pass"). The same calls on the same numbers: the same bits.
    void centre_row(int x0, int x1, int y, ThreadState& ts, glm::dvec3* colour, std::uint32_t* surface = nullptr,
                    bool* ground = nullptr) const;
    // The camera ray through (px, py), as sample() traces it; false
    // outside a fisheye's circle.
    bool ray(double px, double py, glm::dvec3& o, glm::dvec3& d) const { return camera_.ray_unnormalised(px, py, o, d); }
    const csg::Scene& scene() const { return shader_.scene(); }
    // The solid's unit normal at `hit` (ThreadState::hit), point p.
    glm::dvec3 normal(const TraceHit& hit, const glm::dvec3& p) const { return shader_.normal(hit, p); }
    // Only the surface a sample through (px, py) would see (Shader::surface).
    std::uint32_t surface(double px, double py, ThreadState& ts, bool traced) const;
    // Depth of field: one sample through (px, py) from lens point `lens`.
    glm::dvec3 lens_sample(double px, double py, glm::dvec2 lens, ThreadState& ts, bool traced) const;
    // The mean of `pattern`'s samples in pixel (x, y).
    glm::dvec3 mean(const SamplePattern& pattern, int x, int y, ThreadState& ts, bool traced) const {
        const int n = pattern.count();
        if (n == 1) return sample(x + 0.5, y + 0.5, ts, traced, nullptr);  // the centre: no jitter, no generator
        std::uint64_t rng = SamplePattern::pixel_rng(seed_, x, y);
        glm::dvec3 sum(0.0);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 s = pattern.offset(i, rng);
            sum += sample(x + s.x, y + s.y, ts, traced, nullptr);
        }
        return sum / double(n);
    }

    // Stores pixel (x, y), the mean of `samples` samples, with their
    // coverage (--alpha), and starts the next pixel's coverage at 0.
    void put(int x, int y, const glm::dvec3& c, int samples) const {
        if (alpha()) store_.color_alpha(x, y, c, hits_ / samples, shader_.miss(), alpha_ == Alpha::Premultiplied);
        else store_.color(x, y, c);
        hits_ = 0;
    }

    // put(x, y, c, 1), where c's 8-bit codes are known (`rgb`, red in the
    // low byte): an 8-bit image without coverage stores them as they are.
    void put_codes(int x, int y, const glm::dvec3& c, std::uint32_t rgb) const {
        if (!codes_kept()) return put(x, y, c, 1);
        store_.codes(x, y, rgb);
        hits_ = 0;
    }

    // Whether put_codes() stores the codes as they are (an 8-bit image
    // without coverage): put_codes_row() then applies.
    bool codes_kept() const { return !alpha() && store_.bytes(); }
    // put_codes() of pixels [x, x + n) of row y, where codes_kept(); `skip[i]`:
    // pixel x + i not stored.
    void put_codes_row(int x, int y, int n, const std::uint32_t* rgb, const bool* skip) const {
        assert(codes_kept());
        store_.codes_row(x, y, n, rgb, skip);
        hits_ = 0;
    }

    // put(x, y, miss(), 1) for pixels [x0, x1) of row y with nothing
    // covered (a culled block's row): without --alpha, filled as one run.
    void put_misses(int x0, int x1, int y) const {
        hits_ = 0;
        if (!alpha()) return store_.fill(x0, x1, y, shader_.miss());
        for (int x = x0; x < x1; ++x) put(x, y, shader_.miss(), 1);
    }

    // Coverage: the samples of the pixel being shaded that hit a solid (a
    // sample seeing a ghost over the background counts the ghost's
    // opacity). A pixel is shaded start to end on one thread, so it is a
    // thread-local count, reset per pixel.
    static double covered() { return hits_; }
    static void set_covered(double hits) { hits_ = hits; }
    // What the last sample added to covered().
    static double last_cover() { return last_; }
    static void set_last_cover(double cover) { last_ = cover; }

private:
    glm::dvec3 trace(const glm::dvec3& o, const glm::dvec3& d, ThreadState& ts, std::uint32_t* surface) const;

    const CameraModel& camera_;
    const Shader& shader_;
    const GhostLayers* ghosts_;
    const PathTracer* path_;
    PixelStore& store_;
    Alpha alpha_;
    std::uint64_t seed_;
    bool plain_;  // no ghosts, no path tracer, no coverage: a sample is the shader's radiance
    static inline thread_local double hits_ = 0;
    static inline thread_local double last_ = 0;
};

}  // namespace kerf::render
