// cap_triangles(): a polygon with holes cut into triangles. Judged by the
// closed forms of the region (its area, the outer area minus the holes')
// and by the edges: every boundary edge is used by exactly one triangle,
// in its own direction, and every other edge by two triangles running it
// both ways — so the cap closes a mesh whatever triangles it picked.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "interpreter/modules/cap_triangles.hpp"

using namespace kerf::eval;

namespace {

using Ring = std::vector<glm::dvec2>;

Ring square(double x0, double y0, double s, bool clockwise) {
    Ring r{{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
    if (clockwise) std::reverse(r.begin(), r.end());
    return r;
}

void check_cap(const std::vector<Ring>& rings, double area, bool by_id = true) {
    INFO(rings.size() << " rings, area " << area);
    const auto tris = cap_triangles(rings);
    std::vector<glm::dvec2> p;
    for (const Ring& r : rings) p.insert(p.end(), r.begin(), r.end());
    double sum = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> runs;
    for (const auto& t : tris) {
        const glm::dvec2 a = p[t[0]], b = p[t[1]], c = p[t[2]];
        const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        CHECK(twice >= 0);  // counter-clockwise (or of no area)
        sum += twice / 2;
        for (int k = 0; k < 3; ++k) ++runs[{t[k], t[(k + 1) % 3]}];
    }
    CHECK(sum == Approx(area).epsilon(1e-12));
    if (!by_id) return;
    std::uint32_t first = 0;
    for (const Ring& r : rings) {  // each boundary edge once, forwards, and never backwards
        for (std::uint32_t i = 0; i < r.size(); ++i) {
            const std::uint32_t u = first + i, v = first + (i + 1) % std::uint32_t(r.size());
            CHECK(runs[{u, v}] == 1);
            CHECK(runs[{v, u}] == 0);
            runs.erase({u, v});
            runs.erase({v, u});
        }
        first += std::uint32_t(r.size());
    }
    for (const auto& [edge, n] : runs) {  // inner edges: once each way
        INFO(edge.first << " -> " << edge.second);
        CHECK(n == 1);
        CHECK(runs.count({edge.second, edge.first}) == 1);
    }
}

}  // namespace

TEST_CASE("cap triangles cover a convex and a concave outline") {
    check_cap({square(0, 0, 2, false)}, 4);
    check_cap({{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}}}, 20);  // an L
    Ring star;
    for (int i = 0; i < 10; ++i) {
        const double a = M_PI * i / 5, r = i % 2 ? 1 : 3;
        star.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    check_cap({star}, 10 * 0.5 * 3 * 1 * std::sin(M_PI / 5));
}

TEST_CASE("cap triangles leave the holes out") {
    check_cap({square(0, 0, 10, false), square(2, 2, 2, true)}, 96);
    // Holes side by side, one behind the other along +x.
    check_cap({square(0, 0, 10, false), square(1, 4, 2, true), square(4, 4, 2, true), square(7, 4, 2, true),
               square(4, 7, 2, true)},
              100 - 4 * 4);
    // A hole touching the boundary inside an edge, and at a corner (Clipper
    // may keep such a hole apart): there the two corners are one point and
    // the triangles use either (twist_slices.cpp welds them), so only the area is judged.
    check_cap({square(0, 0, 10, false), {{8, 5}, {9, 6}, {10, 5}, {9, 4}}}, 98);
    const Ring pentagon{{0, 0}, {10, 0}, {12, 5}, {10, 10}, {0, 10}};
    check_cap({pentagon, {{10, 5}, {11, 6}, {12, 5}, {11, 4}}, square(1, 1, 1, true)}, 107, false);
    // A ring of many holes in a disc-like outline.
    Ring outer;
    for (int i = 0; i < 40; ++i) outer.emplace_back(20 * std::cos(M_PI * i / 20), 20 * std::sin(M_PI * i / 20));
    std::vector<Ring> rings{outer};
    double area = 40 * 0.5 * 400 * std::sin(M_PI / 20);
    for (int k = 0; k < 8; ++k) {
        const double a = M_PI * k / 4;
        rings.push_back(square(10 * std::cos(a) - 1, 10 * std::sin(a) - 1, 2, true));
        area -= 4;
    }
    check_cap(rings, area);
}
