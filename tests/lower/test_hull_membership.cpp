// The solids hull() and minkowski() lower to, point by point: random points
// classified by the tracer (the spans of a ray through the point) against
// an independent closed-form rule — within r of the box for a rounded box,
// positive barycentric coordinates for a tetrahedron's hull — at tiny,
// ordinary and huge scales (docs/lowering.md, "Hull, Minkowski, resize").
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include "render/tracer/tracer.hpp"
#include "tests/lower/script_scene.hpp"

namespace {

// Inside according to the tracer: a ray along a slanted direction through
// p, started well outside, has a span around p.
bool traced_inside(const kerf::render::CsgTracer& tr, kerf::render::TraceScratch& scratch, const glm::dvec3& p,
                   double size) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, 0.31, 0.17));
    kerf::render::TraceRay ray{p - 4 * size * d, d, 0, 8 * size};
    std::vector<kerf::render::Span> spans;
    tr.inside_spans(ray, scratch, spans);
    const double t = 4 * size;
    for (const auto& s : spans)
        if (s.t0 < t && t < s.t1) return true;
    return false;
}

// Compares the two classifications on `n` points of `box`, skipping points
// the oracle puts within `margin` of the surface (`oracle` returns the
// signed distance-like value: negative inside).
void agree(const std::string& text, const kerf::csg::Aabb& box, double margin,
           const std::function<double(const glm::dvec3&)>& oracle, int n = 4000) {
    const kerf::csg::Scene scene = kerf::test::lowered(text);
    const kerf::render::CsgTracer tracer(scene, false);
    kerf::render::TraceScratch scratch;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const double size = glm::length(box.hi - box.lo);
    int inside = 0, checked = 0, wrong = 0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 p = box.lo + (box.hi - box.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const double v = oracle(p);
        if (std::abs(v) < margin) continue;
        ++checked;
        inside += v < 0;
        if ((v < 0) != traced_inside(tracer, scratch, p, size)) ++wrong;
    }
    INFO(text << ": " << wrong << " of " << checked << " points disagree, " << inside << " inside");
    CHECK(wrong == 0);
    CHECK(inside > checked / 20);  // both kinds of point well represented
    CHECK(inside < checked * 19 / 20);
}

double box_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 q = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0));
    return glm::length(q);
}

std::string num(double x) {
    std::ostringstream o;
    o.precision(17);
    o << x;
    return o.str();
}

}  // namespace

TEST_CASE("a rounded box from minkowski() and from hull() of spheres holds exactly the points within r of the box",
          "[minkowski][hull]") {
    for (double s : {1e-4, 1.0, 1e4}) {
        INFO("scale " << s);
        const glm::dvec3 lo(0), hi = s * glm::dvec3(2, 3, 4);
        const double r = 0.5 * s;
        auto oracle = [&](const glm::dvec3& p) { return box_distance(p, lo, hi) - r; };
        const kerf::csg::Aabb around{lo - glm::dvec3(1.2 * r), hi + glm::dvec3(1.2 * r)};
        agree("minkowski() { cube([" + num(2 * s) + ", " + num(3 * s) + ", " + num(4 * s) + "]); sphere(" + num(r) +
                  "); }",
              around, 1e-7 * s, oracle);
        agree("hull() for (x = [0, " + num(2 * s) + "], y = [0, " + num(3 * s) + "], z = [0, " + num(4 * s) +
                  "]) translate([x, y, z]) sphere(" + num(r) + ");",
              around, 1e-7 * s, oracle);
    }
}

TEST_CASE("hull() of a tetrahedron's corners and inner points holds exactly the tetrahedron", "[hull]") {
    const glm::dvec3 a(0, 0, 0), b(2, 0.1, 0), c(0.3, 3, 0.2), d(0.1, 0.2, 4);
    const glm::dmat3 m(b - a, c - a, d - a);
    const glm::dmat3 inv = glm::inverse(m);
    auto oracle = [&](const glm::dvec3& p) {
        const glm::dvec3 l = inv * (p - a);
        return -std::min({l.x, l.y, l.z, 1 - l.x - l.y - l.z});  // negative inside
    };
    agree("hull() { polyhedron([[0, 0, 0], [2, 0.1, 0], [0.3, 3, 0.2], [0.1, 0.2, 4], [0.5, 0.5, 0.5]], "
          "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]); translate([0.2, 0.2, 0.2]) cube(0.1); }",
          {glm::dvec3(-0.2), glm::dvec3(2.2, 3.2, 4.2)}, 1e-7, oracle);
}

TEST_CASE("degenerate hulls: collinear balls are a capsule, a hull of a flat set has no volume", "[hull]") {
    // Three balls on a line: the capsule between the outer two.
    auto capsule = [](const glm::dvec3& p) {
        const double t = std::clamp(p.x, 0.0, 6.0);
        return glm::length(p - glm::dvec3(t, 0, 0)) - 1;
    };
    agree("hull() { sphere(1); translate([2, 0, 0]) sphere(1); translate([6, 0, 0]) sphere(1); }",
          {glm::dvec3(-1.5), glm::dvec3(7.5, 1.5, 1.5)}, 1e-7, capsule);
    const auto flat = kerf::test::lowered("hull() { polyhedron([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], "
                                          "[[0, 1, 2], [1, 3, 2], [0, 2, 1], [1, 2, 3]]); }");
    CHECK(flat.root == kerf::csg::kNone);
}

TEST_CASE("a 2D rounded rectangle from minkowski() with a circle, extruded, holds exactly its points", "[minkowski]") {
    auto oracle = [](const glm::dvec3& p) {
        const double d = box_distance({p.x, p.y, 0}, glm::dvec3(0), glm::dvec3(2, 3, 0)) - 0.5;
        return std::max(d, std::max(-p.z, p.z - 2));
    };
    agree("linear_extrude(height = 2) rotate(0) minkowski() { square([2, 3]); circle(0.5); }",
          {glm::dvec3(-0.7, -0.7, -0.3), glm::dvec3(2.7, 3.7, 2.3)}, 1e-7, oracle);
    agree("linear_extrude(height = 2) hull() for (x = [0, 2], y = [0, 3]) translate([x, y]) circle(0.5);",
          {glm::dvec3(-0.7, -0.7, -0.3), glm::dvec3(2.7, 3.7, 2.3)}, 1e-7, oracle);
}
