#include "render/pixel_sampler.hpp"

#include <limits>

namespace kerf::render {

namespace {
thread_local double hits = 0;
thread_local double last = 0;  // what the last sample added to `hits`
}  // namespace

double PixelSampler::covered() { return hits; }
void PixelSampler::set_covered(double h) { hits = h; }
double PixelSampler::last_cover() { return last; }
void PixelSampler::set_last_cover(double cover) { last = cover; }

void PixelSampler::put(int x, int y, const glm::dvec3& c, int samples) const {
    if (alpha()) store_.color_alpha(x, y, c, hits / samples, shader_.miss(), alpha_ == Alpha::Premultiplied);
    else store_.color(x, y, c);
    hits = 0;
}

// The colour seen along (o, d); `surface` as Shader::radiance.
glm::dvec3 PixelSampler::trace(const glm::dvec3& o, const glm::dvec3& d, ThreadState& ts, std::uint32_t* surface) const {
    const TraceRay ray{o, d, 0, std::numeric_limits<double>::infinity()};
    auto one = [&](std::uint32_t* id) {
        if (path_) {
            std::uint32_t seen = 0;
            const glm::dvec3 c = path_->radiance(o, d, ts, &seen);
            if (id) *id = seen;
            // The studio ground is a shadow catcher, not a surface that
            // scatters: where a camera ray misses the solid, the shader
            // draws it (elsewhere the same miss colour as the path's).
            if (seen == 0) return shader_.missed(ray, ts);
            return c;
        }
        return shader_.radiance(ray, 0, ts, id);
    };
    if (!alpha()) {
        const glm::dvec3 c = one(surface);
        return ghosts_ ? ghosts_->over(ray, c, ts, nullptr, surface) : c;
    }
    std::uint32_t id = 0;
    glm::dvec3 c = one(&id);
    if (surface) *surface = id;
    double ghost = 0;
    if (ghosts_) c = ghosts_->over(ray, c, ts, &ghost, surface);
    last = id != 0 ? 1.0 : ghost;
    hits += last;
    return c;
}

glm::dvec3 PixelSampler::sample(double px, double py, ThreadState& ts, bool traced, std::uint32_t* surface) const {
    ++ts.rays.primary;
    glm::dvec3 o, d;
    if (!traced || !camera_.ray_unnormalised(px, py, o, d)) {  // culled, or outside a fisheye's circle
        if (surface) *surface = 0;
        return shader_.miss();
    }
    return trace(o, d, ts, surface);
}

std::uint32_t PixelSampler::surface(double px, double py, ThreadState& ts, bool traced) const {
    ++ts.rays.primary;
    glm::dvec3 o, d;
    if (!traced || !camera_.ray_unnormalised(px, py, o, d)) return 0;
    return shader_.surface(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, ts);
}

glm::dvec3 PixelSampler::lens_sample(double px, double py, glm::dvec2 lens, ThreadState& ts, bool traced) const {
    ++ts.rays.primary;
    if (!traced) return shader_.miss();
    glm::dvec3 o, d;
    camera_.ray_through_lens(px, py, lens, o, d);
    return trace(o, d, ts, nullptr);
}

glm::dvec3 PixelSampler::mean(const SamplePattern& pattern, int x, int y, ThreadState& ts, bool traced) const {
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

}  // namespace kerf::render
