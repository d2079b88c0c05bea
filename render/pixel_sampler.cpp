#include "render/pixel_sampler.hpp"

#include <limits>
#include <stdexcept>

namespace kerf::render {

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
    last_ = id != 0 ? 1.0 : ghost;
    hits_ += last_;
    return c;
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

void PixelSampler::centre_row(int x0, int x1, int y, ThreadState& ts, glm::dvec3* colour, std::uint32_t* surface,
                              bool* ground) const {
    const CsgTracer& tracer = shader_.tracer();
    const int n = x1 - x0;
    if (n < 0 || n > kMaxRow) throw std::logic_error("centre_row: more pixels than a block's row");
    ts.rays.primary += std::uint64_t(n);
    TraceRay rays[kMaxRow];
    bool ok[kMaxRow], solid[kMaxRow];
    // (Written by the trace where it hits, by the shading loop where not:
    // left uninitialised, not zeroed for every row.)
    union Hits {
        TraceHit at[kMaxRow];
        Hits() {}
    } hits;
    for (int i = 0; i < n; ++i) {
        rays[i].tnear = 0;
        rays[i].tfar = std::numeric_limits<double>::infinity();
        ok[i] = camera_.ray_unnormalised(x0 + i + 0.5, y + 0.5, rays[i].o, rays[i].d);
        if (!ok[i]) rays[i].o = rays[i].d = glm::dvec3(0.0);
    }
    AheadSpans ahead[kMaxRow];
    const bool solved = tracer.solve_ahead(rays, n, ahead);
    for (int i = 0; i < n; ++i) {
        ts.scratch.ahead = solved ? &ahead[i] : nullptr;
        solid[i] = ok[i] && tracer.intersect(rays[i], hits.at[i], ts.scratch);
    }
    ts.scratch.ahead = nullptr;
    for (int i = 0; i < n; ++i) {
        if (!solid[i]) hits.at[i] = TraceHit{};
        ts.on_ground = false;
        if (!ok[i]) {  // outside a fisheye's circle
            colour[i] = shader_.miss();
            if (surface) surface[i] = 0;
        } else {
            colour[i] = shader_.radiance(rays[i], solid[i], hits.at[i], 0, ts, surface ? &surface[i] : nullptr);
        }
        if (ground) ground[i] = ts.on_ground;
    }
}

}  // namespace kerf::render
