// convex_hull (lower/convex_hull.hpp): qhull for full-dimensional sets and
// the flat cases by dimension, with the extremes the spec asks for —
// collinear and coplanar points, nearly coplanar ones, tiny and huge
// scales — against closed-form volumes and corner counts.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <random>

#include "lower/convex_hull.hpp"

using kerf::convex_hull;

namespace {

std::vector<glm::dvec3> cube_with_inside(double s, const glm::dvec3& at) {
    std::vector<glm::dvec3> p;
    for (int k = 0; k < 8; ++k) p.push_back(at + s * glm::dvec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.01, 0.99);
    for (int i = 0; i < 200; ++i) p.push_back(at + s * glm::dvec3(u(rng), u(rng), u(rng)));
    return p;
}

}  // namespace

TEST_CASE("convex_hull of a cube's corners and inner points: 8 corners, 6 square faces", "[hull]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        INFO("scale " << s);
        const auto h = convex_hull(cube_with_inside(s, glm::dvec3(3 * s, -s, 1e3 * s)));
        CHECK(h.dim == 3);
        CHECK(h.points.size() == 8);
        CHECK(h.faces.size() == 6);
        for (const auto& f : h.faces) CHECK(f.size() == 4);
        CHECK(kerf::hull_volume(h) == Approx(s * s * s).epsilon(1e-12));
        // Outward normals, faces counter-clockwise about them.
        for (std::size_t f = 0; f < h.faces.size(); ++f) {
            const auto& l = h.faces[f];
            const glm::dvec3 n = glm::cross(h.points[l[1]] - h.points[l[0]], h.points[l[2]] - h.points[l[1]]);
            CHECK(glm::dot(n, h.normals[f]) > 0);
        }
    }
}

TEST_CASE("convex_hull of flat sets: a point, a segment, a polygon", "[hull]") {
    auto h = convex_hull({{1, 2, 3}, {1, 2, 3}});
    CHECK(h.dim == 0);
    h = convex_hull({{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}});
    CHECK(h.dim == 1);
    REQUIRE(h.points.size() == 2);
    CHECK(glm::length(h.points[0] - h.points[1]) == Approx(std::sqrt(27.0)));
    // A square with a point in it and one on an edge, tilted out of every axis plane.
    const glm::dvec3 e1 = glm::normalize(glm::dvec3(1, 2, 3)), e2 = glm::normalize(glm::cross(e1, glm::dvec3(0, 0, 1)));
    std::vector<glm::dvec3> sq;
    for (glm::dvec2 q : {glm::dvec2(0, 0), {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}}) sq.push_back(q.x * e1 + q.y * e2);
    h = convex_hull(sq);
    CHECK(h.dim == 2);
    CHECK(h.points.size() == 4);
    CHECK(std::abs(glm::dot(h.normal, glm::cross(e1, e2))) == Approx(1));
    // Nearly coplanar: a 1e-12 bump on a unit square stays flat, a 1e-6 one does not.
    std::vector<glm::dvec3> bumped{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1e-12}};
    CHECK(convex_hull(bumped).dim == 2);
    for (double bump : {1e-6, 1e-9}) {
        bumped.back().z = bump;
        h = convex_hull(bumped);
        CHECK(h.dim == 3);
        CHECK(h.points.size() == 5);
        CHECK(kerf::hull_volume(h) == Approx(bump / 3).epsilon(1e-6));
    }
    CHECK(convex_hull({}).dim == -1);
}

TEST_CASE("convex_hull of 10,000 points on a sphere keeps them all as corners", "[hull]") {
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 10000; ++i) p.push_back(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
    const auto t0 = std::chrono::steady_clock::now();
    const auto h = convex_hull(p);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    WARN("convex_hull of 10,000 sphere points: " << ms << " ms");
    CHECK(h.points.size() == 10000);
    CHECK(kerf::hull_volume(h) < 4.0 / 3 * M_PI);
    CHECK(kerf::hull_volume(h) > 0.99 * 4.0 / 3 * M_PI);
}
