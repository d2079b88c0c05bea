// The units between a bare sphere and a point light (toward_light.hpp):
// the build, and a slot's listing on first use.
#include "render/tracer/toward_light.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::render {

namespace {
double l1(const glm::dvec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }
}  // namespace

void TowardLight::build_radii(const std::vector<Ball>& balls, const std::vector<double>& leaf_eps_of_unit,
                              double eps_per_distance, double frame_radius, const csg::Aabb& reach,
                              const std::vector<glm::dvec3>& point_lights) {
    *this = TowardLight{};
    if (balls.size() < 2 || balls.size() > kMaxUnits || point_lights.empty() || reach.empty()) return;
    const double mag = l1(reach.lo) + l1(reach.hi);
    for (const glm::dvec3& p : point_lights) {
        if (lights.size() == std::size_t(kMaxLights)) break;
        // The shader's ray ends at o + |p - o|·(p - o)/|p - o|: p to a few
        // ulps of |o| + |p - o|; 1e-9 of the magnitudes is far beyond.
        lights.push_back({p, 1e-9 * (l1(p) + mag + frame_radius)});
    }
    // The shader starts a shadow ray 100 degenerate rules off the hit point
    // (CsgTracer::surface_offset: 100·(leaf_eps + eps_per_distance·|p|)),
    // and the hit lies on the sphere to round-off: twice that, plus 1e-4 of
    // the radius, bounds it (checked per ray all the same: light_of).
    radius.resize(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        if (!(b.r >= 0)) return lights.clear();
        r_small = std::min(i == 0 ? b.r : r_small, b.r);
        radius[i] = b.r * (1 + 1e-4) + 200 * (leaf_eps_of_unit[i] + eps_per_distance * (l1(b.c) + b.r)) + 1e-12 * l1(b.c);
    }
}

void TowardLight::attach(const std::vector<Ball>& balls, const csg::Aabb& reach, const SphereGrid& crowd_grid) {
    if (lights.empty()) return;
    if (crowd_grid.empty()) {
        own_grid.build(reach, balls);
        if (own_grid.empty()) return lights.clear();
        grid = &own_grid;
    } else {
        grid = &crowd_grid;
    }
    r_small = std::max(r_small, 1e-300);
    units = balls.size();
    // Zeroed pages, touched only where a lit sphere's slot is written.
    slots.reset(static_cast<std::uint32_t*>(std::calloc(lights.size() * units * kSlot, sizeof(std::uint32_t))));
    if (!slots) lights.clear();
}

std::uint32_t TowardLight::fill(int k, std::uint32_t unit, const std::vector<Ball>& balls, std::uint32_t* slot) const {
    const SphereGrid& g = *grid;
    const glm::dvec3 c = balls[unit].c, a = lights[std::size_t(k)].p - c;
    const double rcap = std::max(radius[unit], lights[std::size_t(k)].rho);
    const double a2 = glm::dot(a, a), h_min = std::min({g.h.x, g.h.y, g.h.z});
    // One slack for every unit, beyond the sphere test's round-off on any
    // of them: relative 1e-9 of the distances (and 1e-14 of their square
    // over the smallest radius, a grazing chord's), 1e-6 of the radii.
    const double dist = 2 * (l1(a) + g.size + l1(c - g.lo)), r_big = g.size;
    const double slack = 1e-6 * (r_big + rcap) + 1e-9 * dist + 1e-14 * dist * dist / r_small;
    std::uint32_t found[kMaxList];
    std::uint32_t count = 0;
    bool full = !(slack < 0.25 * h_min);
    // The capsule's axis, sampled every `step` at most over the part that
    // comes within `half` of the grid's box; every point within rcap +
    // slack of the axis lies in the cube of half-size `half` round a
    // sample, and so does every cell listing a ball that reaches it. A
    // cell the last sample's cube held is not visited again.
    const double step = 0.25 * h_min, half = rcap + slack + 0.5 * step + g.margin;
    double s0 = 0, s1 = 1;
    for (int i = 0; i < 3 && !full; ++i) {
        const double box_lo = g.lo[i] - half, box_hi = g.lo[i] + g.n[i] * g.h[i] + half;
        if (a[i] == 0) {
            if (c[i] < box_lo || c[i] > box_hi) s1 = -1;
            continue;
        }
        double t0 = (box_lo - c[i]) / a[i], t1 = (box_hi - c[i]) / a[i];
        if (t0 > t1) std::swap(t0, t1);
        s0 = std::max(s0, t0);
        s1 = std::min(s1, t1);
    }
    const double span = std::sqrt(a2) * std::max(0.0, s1 - s0);
    const double steps = std::ceil(span / step);
    if (!(steps <= kMaxSteps)) full = true;
    const double inv_a2 = a2 > 0 ? 1 / a2 : 0;
    const auto meets = [&](std::uint32_t j) {
        const Ball& b = balls[j];
        const glm::dvec3 w = b.c - c;
        const double s = std::clamp(glm::dot(w, a) * inv_a2, 0.0, 1.0);
        const glm::dvec3 q = w - s * a;
        const double reach = b.r + rcap + slack;
        return !(glm::dot(q, q) > reach * reach);
    };
    const std::uint32_t* start = g.start.data();
    const std::uint32_t* items = g.items.data();
    int prev_lo[3] = {1, 1, 1}, prev_hi[3] = {0, 0, 0};  // (empty)
    for (int i = 0; !full && s1 >= s0 && i <= int(steps); ++i) {
        const glm::dvec3 x = c + (s0 + (s1 - s0) * (steps > 0 ? i / steps : 0.0)) * a;
        int lo[3], hi[3];
        for (int axis = 0; axis < 3; ++axis) {
            const double top = double(g.n[axis] - 1);
            lo[axis] = int(std::clamp((x[axis] - half - g.lo[axis]) * g.inv_h[axis], 0.0, top));
            hi[axis] = int(std::clamp((x[axis] + half - g.lo[axis]) * g.inv_h[axis], 0.0, top));
        }
        if (lo[0] == prev_lo[0] && lo[1] == prev_lo[1] && lo[2] == prev_lo[2] && hi[0] == prev_hi[0] &&
            hi[1] == prev_hi[1] && hi[2] == prev_hi[2])
            continue;
        for (int z = lo[2]; z <= hi[2] && !full; ++z)
            for (int y = lo[1]; y <= hi[1] && !full; ++y)
                for (int xc = lo[0]; xc <= hi[0] && !full; ++xc) {
                    if (xc >= prev_lo[0] && xc <= prev_hi[0] && y >= prev_lo[1] && y <= prev_hi[1] && z >= prev_lo[2] &&
                        z <= prev_hi[2])
                        continue;
                    const std::size_t cell = (std::size_t(z) * g.n[1] + std::size_t(y)) * g.n[0] + std::size_t(xc);
                    for (std::uint32_t e = start[cell]; e < start[cell + 1] && !full; ++e) {
                        const std::uint32_t j = items[e];
                        if (j == unit || std::find(found, found + count, j) != found + count || !meets(j)) continue;
                        if (count == kMaxList) full = true;
                        else found[count++] = j;
                    }
                }
        for (int axis = 0; axis < 3; ++axis) prev_lo[axis] = lo[axis], prev_hi[axis] = hi[axis];
    }
    if (full) {
        std::atomic_ref<std::uint32_t>(slot[0]).store(kFull, std::memory_order_release);
        return kFull;
    }
    for (std::uint32_t i = 0; i < count; ++i)
        std::atomic_ref<std::uint32_t>(slot[1 + i]).store(found[i], std::memory_order_relaxed);
    std::atomic_ref<std::uint32_t>(slot[0]).store(count + 1, std::memory_order_release);
    return count + 1;
}

}  // namespace kerf::render
