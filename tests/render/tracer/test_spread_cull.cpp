// spread_cull_bounds (render/tracer/spread_cull.cpp): a crowd of spread
// sizes is culled by its `keep` largest balls and one merged ball round the
// rest. A tile is dropped when its hull leaves the merged ball out, so that
// ball must hold every other unit's ball grown as tile_cull.cpp grows it
// (by rel·|c - o|₁, rel up to 1e-5, which for a unit at distance d from the
// merged centre adds at most sqrt(3)·rel·d); checked here in long double on
// crowds at 1e-3 to 1e6 scale and far from the origin. A merged radius
// 1e-3 short of what the code computes fails the containment check (the
// check's own margin is far below it).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/tracer/build.hpp"

using kerf::render::Ball;

namespace {

long double dist(const glm::dvec3& a, const glm::dvec3& b) {
    const long double x = (long double)a.x - b.x, y = (long double)a.y - b.y, z = (long double)a.z - b.z;
    return std::sqrt(x * x + y * y + z * z);
}

}  // namespace

TEST_CASE("a spread crowd's merged ball holds every small unit's grown ball", "[tracer][cull]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const std::size_t keep = 8;
    int crowds = 0;
    for (double scale : {1e-3, 1.0, 1e4}) {
        for (double far : {0.0, 1e6}) {
            for (int trial = 0; trial < 20; ++trial) {
                // keep large balls on a ring, 60-400 tiny ones crowding one spot.
                std::vector<Ball> balls;
                std::vector<kerf::csg::Aabb> boxes;
                const glm::dvec3 spot(far + scale * u(rng), far * 0.5 + scale * u(rng), scale * u(rng));
                for (std::size_t i = 0; i < keep; ++i) {
                    const double a = 6.283185307179586 * double(i) / keep;
                    balls.push_back({spot + 20.0 * scale * glm::dvec3(std::cos(a), std::sin(a), 0.1 * u(rng)),
                                     scale * (6 + u(rng))});
                }
                const int small = 60 + int(170 * (1 + u(rng)));
                for (int i = 0; i < small; ++i)
                    balls.push_back({spot + scale * glm::dvec3(u(rng), u(rng), u(rng)), scale * 0.05 * (1.1 + u(rng))});
                for (const Ball& b : balls) {
                    kerf::csg::Aabb box;
                    box.extend(b.c - glm::dvec3(b.r));
                    box.extend(b.c + glm::dvec3(b.r));
                    boxes.push_back(box);
                }
                const auto bounds = kerf::render::spread_cull_bounds(balls, boxes, keep);
                REQUIRE(bounds.size() == keep + 1);
                ++crowds;
                // The kept ones are the largest balls, as given.
                std::vector<bool> kept(balls.size(), false);
                for (std::size_t k = 0; k < keep; ++k) {
                    const auto it = std::find_if(balls.begin(), balls.end(), [&](const Ball& b) {
                        return b.c == bounds[k].ball.c && b.r == bounds[k].ball.r;
                    });
                    REQUIRE(it != balls.end());
                    kept[std::size_t(it - balls.begin())] = true;
                }
                CHECK(std::count(kept.begin(), kept.end(), true) == long(keep));
                const Ball& m = bounds[keep].ball;
                const kerf::csg::Aabb& mbox = bounds[keep].box;
                int short_by_1e3 = 0;
                for (std::size_t i = 0; i < balls.size(); ++i) {
                    if (kept[i]) continue;
                    const long double d = dist(balls[i].c, m.c);
                    const long double need = d * (1 + std::sqrt(3.0L) * 1e-5L) + balls[i].r;
                    CHECK(m.r >= need);
                    if ((long double)m.r * (1 - 1e-3L) < need) ++short_by_1e3;
                    for (int a = 0; a < 3; ++a) {
                        CHECK(mbox.lo[a] <= boxes[i].lo[a]);
                        CHECK(mbox.hi[a] >= boxes[i].hi[a]);
                    }
                }
                // The check can fail: a radius 1e-3 smaller leaves some unit out.
                CHECK(short_by_1e3 > 0);
            }
        }
    }
    CHECK(crowds == 120);
}

TEST_CASE("a crowd whose small units do not crowd one spot is not merged", "[tracer][cull]") {
    // Small balls spread as wide as the large ones: the merged ball would be
    // larger than half the largest unit, so every unit is culled on its own.
    std::vector<Ball> balls;
    std::vector<kerf::csg::Aabb> boxes;
    for (int i = 0; i < 300; ++i) {
        const double a = 0.05 * i;
        balls.push_back({glm::dvec3(10 * std::cos(a), 10 * std::sin(a), 0.01 * i), i < 8 ? 2.0 : 0.1});
        kerf::csg::Aabb box;
        box.extend(balls.back().c - glm::dvec3(balls.back().r));
        box.extend(balls.back().c + glm::dvec3(balls.back().r));
        boxes.push_back(box);
    }
    CHECK(kerf::render::spread_cull_bounds(balls, boxes, 8).empty());
    // Not more balls than it keeps: nothing to merge.
    balls.resize(8);
    boxes.resize(8);
    CHECK(kerf::render::spread_cull_bounds(balls, boxes, 8).empty());
}
