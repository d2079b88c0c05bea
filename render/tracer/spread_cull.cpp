// Culling crowds of spread sizes (tile_cull.cpp; the spiral family): the
// largest units are culled each by its ball, and the many small ones that
// crowd one spot (the spiral's centre) by one ball holding them all, so a
// tile asks kCullUnits + 1 bounds, not thousands (spiral_10000 had no
// culling at all: more than kMaxTwoLevelUnits units).
#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/tracer/build.hpp"

namespace kerf::render {

// Exactness. tile_cull.cpp's ball test grows a ball (c, r) by
// grown_radius: r + abs + rel·|c - o|₁. For a ball (c_i, r_i) at distance
// d_i (L2) from the merged centre C, |c_i - o|₁ <= |C - o|₁ + sqrt(3)·d_i,
// so the merged ball's growth covers the unit's when R >= d_i·(1 +
// sqrt(3)·rel) + r_i; rel (ball_slack) is at most 1e-5, and R takes 1e-4
// of d_i and 1e-9 of the whole beyond that for its own round-off. A tile
// whose hull leaves the merged ball out leaves every unit in it out.
std::vector<CsgTracer::Impl::CullBound> spread_cull_bounds(const std::vector<Ball>& balls,
                                                           const std::vector<csg::Aabb>& boxes, std::size_t keep) {
    const std::size_t n = balls.size();
    if (n <= keep) return {};
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    // Largest first (ties by index: the same bounds on every run).
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return balls[x].r > balls[y].r; });
    glm::dvec3 c(0.0);
    for (std::size_t i = keep; i < n; ++i) c += balls[order[i]].c;
    c /= double(n - keep);
    double big = 0;
    for (std::size_t i = keep; i < n; ++i) {
        const Ball& b = balls[order[i]];
        const double d = glm::length(b.c - c);
        big = std::max(big, d * (1 + 1e-4) + b.r);
    }
    big *= 1 + 1e-9;
    // Only a tight crowd: a merged ball smaller than half the largest unit
    // culls about as well as its units would (cells_1000's small cells lie
    // all along its spiral: no merge, and per-unit culling as before).
    if (!(big <= 0.5 * balls[order[0]].r)) return {};
    std::vector<CsgTracer::Impl::CullBound> bounds;
    for (std::size_t i = 0; i < keep; ++i) bounds.push_back({balls[order[i]], boxes[order[i]]});
    csg::Aabb box;
    for (std::size_t i = keep; i < n; ++i) box.extend(boxes[order[i]]);
    bounds.push_back({Ball{c, big}, box});
    return bounds;
}

}  // namespace kerf::render
