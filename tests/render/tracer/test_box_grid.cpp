// The subtrahend grid (render/tracer/box_grid.hpp) must list every box the
// tracer's own box test keeps: its candidates for a window of a ray, and
// for a point and reach, are checked against brute force over all boxes
// (slab_hit, the test spans() makes; per-axis distance for `near`). Boxes
// of very different sizes, at 1e-6 and 1e6 scale, 1e7 sizes from the origin;
// rays from far away, grazing the cells' planes and the boxes' faces
// (parallel to an axis, on the plane itself), windows from a point to
// longer than the grid.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "render/tracer/ray_state.hpp"

using namespace kerf;
using render::BoxGrid;

namespace {

struct Counts {
    int answered = 0, refused = 0, found = 0;
};

// Every box slab_hit keeps on [t0, t1] must be a candidate, each once.
void check_window(const BoxGrid& g, const std::vector<csg::Aabb>& boxes, const glm::dvec3& o, const glm::dvec3& d,
                  double t0, double t1, Counts& counts) {
    const glm::dvec3 invd = 1.0 / d;
    std::uint32_t out[64];
    const int n = g.candidates(o, d, invd, t0, t1, out, 64);
    if (n < 0) {
        counts.refused++;
        return;
    }
    counts.answered++;
    std::vector<std::uint32_t> got(out, out + n);
    std::sort(got.begin(), got.end());
    CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
    for (std::uint32_t k = 0; k < boxes.size(); ++k) {
        if (!render::slab_hit(boxes[k], o, invd, t0, t1)) continue;
        counts.found++;
        INFO("box " << k << " ray o = (" << o.x << ", " << o.y << ", " << o.z << ") d = (" << d.x << ", " << d.y
                    << ", " << d.z << ") on [" << t0 << ", " << t1 << "]");
        CHECK(std::binary_search(got.begin(), got.end(), k));
    }
}

// Every box within r of x on each axis must be listed.
void check_near(const BoxGrid& g, const std::vector<csg::Aabb>& boxes, const glm::dvec3& x, double r, Counts& counts) {
    std::uint32_t out[64];
    const std::uint32_t* list = nullptr;
    const int n = g.near(x, r, out, 64, list);
    if (n < 0) {
        counts.refused++;
        return;
    }
    counts.answered++;
    std::vector<std::uint32_t> got(list, list + n);
    std::sort(got.begin(), got.end());
    CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
    for (std::uint32_t k = 0; k < boxes.size(); ++k) {
        bool within = true;
        for (int i = 0; i < 3; ++i) within = within && boxes[k].lo[i] <= x[i] + r && x[i] - r <= boxes[k].hi[i];
        if (!within) continue;
        counts.found++;
        INFO("box " << k << " near (" << x.x << ", " << x.y << ", " << x.z << ") r = " << r);
        CHECK(std::binary_search(got.begin(), got.end(), k));
    }
}

}  // namespace

TEST_CASE("tracer subtrahend grid: candidates against brute force over every box", "[render][tracer]") {
    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> u(0, 1);
    for (const double k : {1e-6, 1.0, 1e6}) {
        for (const double far : {0.0, 1e7}) {  // from the origin, in sizes
            const glm::dvec3 c = k * glm::dvec3(far, -0.5 * far, 0.25 * far);
            // A holes-like lattice of tall thin boxes, and scattered ones
            // from a tenth to twice their size, a few of them long slabs.
            std::vector<csg::Aabb> boxes;
            for (int i = 0; i < 12; ++i)
                for (int j = 0; j < 12; ++j) {
                    const glm::dvec3 m = c + k * glm::dvec3(0.25 * (i + 0.5), 0.25 * (j + 0.5), 0.5);
                    boxes.push_back({m - k * glm::dvec3(0.1, 0.1, 1.5), m + k * glm::dvec3(0.1, 0.1, 1.5)});
                }
            for (int i = 0; i < 60; ++i) {
                const glm::dvec3 m = c + k * glm::dvec3(3 * u(rng), 3 * u(rng), 3 * u(rng) - 1);
                glm::dvec3 h = k * glm::dvec3(0.01 + 0.2 * u(rng), 0.01 + 0.2 * u(rng), 0.01 + 0.2 * u(rng));
                if (i % 10 == 0) h[i % 3] = 1.5 * k;
                boxes.push_back({m - h, m + h});
            }
            BoxGrid g;
            g.build(boxes);
            REQUIRE(!g.empty());
            Counts win, near;
            const auto rand_dir = [&] {
                return glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) + 1e-9);
            };
            for (int q = 0; q < 4000; ++q) {
                // A point of interest in the grid, or on a cell plane or a box face.
                glm::dvec3 x = c + k * glm::dvec3(3 * u(rng), 3 * u(rng), 3 * u(rng) - 1);
                glm::dvec3 d = rand_dir();
                const int axis = q % 3;
                if (q % 4 == 1) {  // on a cell plane, parallel to it
                    x[axis] = g.lo[axis] + double(int(u(rng) * g.res[axis])) * g.cell[axis];
                    d[axis] = 0;
                    if (q % 8 == 1) d[(axis + 1) % 3] = 0;  // along a cell edge
                    if (glm::length(d) == 0) d[(axis + 2) % 3] = 1;
                    d = glm::normalize(d);
                } else if (q % 4 == 2) {  // in a box's face plane, parallel to it
                    const csg::Aabb& b = boxes[std::size_t(u(rng) * double(boxes.size()))];
                    x[axis] = u(rng) < 0.5 ? b.lo[axis] : b.hi[axis];
                    d[axis] = 0;
                    d = glm::normalize(d);
                }
                // The ray passes through x at t = s: from nearby or from far away.
                const double s = k * (q % 5 == 0 ? 1e4 : 2 * u(rng));
                const glm::dvec3 o = x - s * d;
                const double lengths[] = {0, 1e-9 * k, 1e-4 * k, 0.2 * k, 2 * k, 50 * k};
                const double len = lengths[q % 6];
                check_window(g, boxes, o, d, s - 0.5 * len, s + 0.5 * len, win);
                const double reach[] = {0, 1e-9 * k, 1e-3 * k, 0.1 * k};
                check_near(g, boxes, x, reach[q % 4], near);
            }
            INFO("scale " << k << " at " << far << ": windows answered " << win.answered << ", refused "
                          << win.refused << "; points answered " << near.answered << ", refused " << near.refused);
            // The grid must answer most short queries (else the test proves nothing).
            CHECK(win.answered > 2500);
            CHECK(near.answered > 3500);
            CHECK(win.found > 1000);
            CHECK(near.found > 1000);
        }
    }
}

TEST_CASE("tracer subtrahend grid: no grid where it would not pay", "[render][tracer]") {
    // Every box covers the whole extent: one cell's worth, left to the BVH.
    std::vector<csg::Aabb> boxes(20, csg::Aabb{glm::dvec3(0), glm::dvec3(1)});
    BoxGrid g;
    g.build(boxes);
    CHECK(g.empty());
}
