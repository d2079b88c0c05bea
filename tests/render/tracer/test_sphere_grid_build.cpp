// SphereGrid::build (render/tracer/sphere_grid.cpp) counts and lists a big
// crowd's balls in two halves, on the arena's threads: each cell must still
// list exactly the units whose grown ball box meets it, in ascending order
// (the walk's ties go by unit index), on 1 and 2 threads alike.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "render/tracer/parallel_build.hpp"
#include "render/tracer/sphere_grid.hpp"

using namespace kerf;
using kerf::render::Ball;
using kerf::render::SphereGrid;

namespace {

// The cells [c0, c1] along axis a that the ball's box grown by the margin
// meets: the cells whose box [lo + c h, lo + (c + 1) h] overlaps it.
void cell_span(const SphereGrid& g, const Ball& b, int a, int& c0, int& c1) {
    const double lo = b.c[a] - b.r - g.margin, hi = b.c[a] + b.r + g.margin;
    c0 = g.n[a] - 1;
    c1 = 0;
    for (int c = 0; c < g.n[a]; ++c) {
        const double cell_lo = g.lo[a] + c * g.h[a], cell_hi = g.lo[a] + (c + 1) * g.h[a];
        if (hi >= cell_lo && lo <= cell_hi) {
            c0 = std::min(c0, c);
            c1 = std::max(c1, c);
        }
    }
}

void check_grid(const std::vector<Ball>& balls, const csg::Aabb& box) {
    SphereGrid one, two;
    tbb::task_arena(1).execute([&] { one.build(box, balls); });
    tbb::task_arena(2).execute([&] { two.build(box, balls); });
    REQUIRE(!one.empty());
    CHECK(one.start == two.start);
    CHECK(one.items == two.items);
    const std::size_t cells = std::size_t(one.n[0]) * one.n[1] * one.n[2];
    REQUIRE(one.start.size() == cells + 1);
    std::size_t unordered = 0;
    for (std::size_t c = 0; c < cells; ++c)
        for (std::uint32_t k = one.start[c] + 1; k < one.start[c + 1]; ++k) unordered += one.items[k - 1] >= one.items[k];
    CHECK(unordered == 0);
    // Each ball in the cells its box meets (away from cell planes, where
    // the build's rounding may take a neighbour: those are not counted).
    std::size_t missing = 0, listed = 0;
    for (std::uint32_t i = 0; i < balls.size(); ++i) {
        int c0[3], c1[3];
        for (int a = 0; a < 3; ++a) cell_span(one, balls[i], a, c0[a], c1[a]);
        for (int z = c0[2]; z <= c1[2]; ++z)
            for (int y = c0[1]; y <= c1[1]; ++y)
                for (int x = c0[0]; x <= c1[0]; ++x) {
                    const std::size_t cell = (std::size_t(z) * one.n[1] + y) * one.n[0] + x;
                    const auto first = one.items.begin() + one.start[cell], last = one.items.begin() + one.start[cell + 1];
                    missing += !std::binary_search(first, last, i);
                    ++listed;
                }
    }
    CHECK(missing == 0);
    CHECK(listed <= one.items.size());
}

}  // namespace

TEST_CASE("a big crowd's sphere grid lists each cell's units in order, the same on 1 and 2 threads", "[render][grid]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10, 10), r(0.05, 0.4);
    for (const std::size_t n : {std::size_t(render::kParallelBuild) + 1, 3 * std::size_t(render::kParallelBuild) + 11}) {
        INFO(n << " balls");
        std::vector<Ball> balls;
        csg::Aabb box;
        for (std::size_t i = 0; i < n; ++i) {
            Ball b{glm::dvec3(u(rng), u(rng), u(rng)), r(rng)};
            if (i % 97 == 5) b = balls[i / 2];  // twins far apart in the list: one in each half
            balls.push_back(b);
            box.extend({b.c - glm::dvec3(b.r), b.c + glm::dvec3(b.r)});
        }
        check_grid(balls, box);
    }
}
