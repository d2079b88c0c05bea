// SVG's attribute languages (interpreter/import/svg_path.hpp) against the
// SVG 1.1 grammar and hand-computed points: path commands, the number
// syntax, smooth-curve reflections, transform lists, strokes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "interpreter/import/svg_path.hpp"

using namespace kerf::eval;

namespace {

bool near(glm::dvec2 a, glm::dvec2 b, double tol = 1e-12) { return glm::length(a - b) <= tol; }

// Signed area of a loop (shoelace).
double area(const svg::Chain& c) {
    double a = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec2 p = c[i], q = c[(i + 1) % c.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2;
}

}  // namespace

TEST_CASE("path data: lines absolute and relative, implicit repeats, run-together numbers", "[svg]") {
    const auto subs = svg::parse_path("m1,1 2 0v2H1z M5-5l1.5.5-.5e1 0", 1e-4);
    REQUIRE(subs.size() == 2);
    CHECK(subs[0].closed);
    REQUIRE(subs[0].points.size() == 4);
    CHECK(near(subs[0].points[1], {3, 1}));  // "2 0" after m is a relative lineto
    CHECK(near(subs[0].points[2], {3, 3}));
    CHECK(near(subs[0].points[3], {1, 3}));
    CHECK_FALSE(subs[1].closed);
    REQUIRE(subs[1].points.size() == 3);
    CHECK(near(subs[1].points[1], {6.5, -4.5}));  // "1.5.5" is 1.5 and .5
    CHECK(near(subs[1].points[2], {1.5, -4.5}));  // "-.5e1" is -5
    // Drawing on after Z starts at the closed subpath's first point.
    const auto after = svg::parse_path("M2 2 h1 v1 z l0 5", 1e-4);
    REQUIRE(after.size() == 2);
    CHECK(near(after[1].points[0], {2, 2}));
    CHECK(near(after[1].points[1], {2, 7}));
}

TEST_CASE("path data: smooth curves reflect the last control point, and only after a curve", "[svg]") {
    // S after C: the first control point is the mirror of C's second.
    const auto a = svg::parse_path("M0 0 C0 1 1 1 1 0 S2 -1 2 0", 1e-6);
    const auto b = svg::parse_path("M0 0 C0 1 1 1 1 0 C1 -1 2 -1 2 0", 1e-6);
    REQUIRE(a[0].points.size() == b[0].points.size());
    for (std::size_t i = 0; i < a[0].points.size(); ++i) CHECK(near(a[0].points[i], b[0].points[i]));
    // T after a line: its control point is the current point, a straight segment.
    const auto t = svg::parse_path("M0 0 L1 0 T3 0", 1e-4);
    for (glm::dvec2 p : t[0].points) CHECK(p.y == 0);
    // A quadratic's points lie on its parabola: x = 2t, y = 4t(1 - t) = x(2 - x).
    const auto q = svg::parse_path("M0 0 Q1 2 2 0", 1e-4);
    for (glm::dvec2 p : q[0].points) CHECK(std::abs(p.y - p.x * (2 - p.x)) <= 1e-12);
}

TEST_CASE("path data: arcs on their circle, radii scaled up, flags either way", "[svg]") {
    // The upper half circle of radius 1 about (1, 0), sweep-flag 1 (positive angle in SVG's y-down frame).
    const auto a = svg::parse_path("M0 0 A1 1 0 0 1 2 0", 1e-4);
    for (glm::dvec2 p : a[0].points) CHECK(std::abs(glm::length(p - glm::dvec2(1, 0)) - 1) <= 1e-12);
    for (glm::dvec2 p : a[0].points) CHECK(p.y <= 1e-12);
    // Radii too small for the chord are scaled up to just span it: the same half circle.
    const auto small = svg::parse_path("M0 0 A0.1 0.1 0 0 1 2 0", 1e-4);
    for (glm::dvec2 p : small[0].points) CHECK(std::abs(glm::length(p - glm::dvec2(1, 0)) - 1) <= 1e-12);
    // Large-arc and sweep flags pick the centre (0, 0) and the long way: a 3/4 disc, area 3π/4.
    const auto big = svg::parse_path("M1 0 A1 1 0 1 1 0 -1 L0 0 Z", 1e-6);
    CHECK(std::abs(std::abs(area(big[0].points)) - 3 * std::numbers::pi / 4) <= 1e-5);
    // A zero radius is a straight line.
    const auto zero = svg::parse_path("M0 0 A0 1 0 0 1 2 0", 1e-4);
    CHECK(zero[0].points.size() == 2);
}

TEST_CASE("path data errors name the character", "[svg]") {
    auto message = [](const char* d) {
        try {
            svg::parse_path(d, 1e-4);
        } catch (const svg::DataError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(message("M0 0 L1") == "expected a number at character 8, got the end");
    CHECK(message("M0 0 X1 1") == "expected a path command at character 6, got 'X'");
    CHECK(message("M0 0 A1 1 0 2 0 1 1") == "expected an arc flag 0 or 1 at character 13, got '2'");
    CHECK(message("M0 0 Z 1 1") == "expected a path command after Z at character 8, got '1'");
    CHECK(message("10 10") == "expected a moveto (M or m) at character 1, got '1'");
}

TEST_CASE("transform lists compose left to right, rotate about a centre, skews", "[svg]") {
    const Map2 m = svg::parse_transform("translate(10) rotate(90, 1 1),scale(2 3)");
    // scale, then the rotation about (1, 1), then the translation.
    CHECK(near(apply(m, {1, 0}), {12, 2}, 1e-12));  // (2, 0), turned about (1, 1) to (2, 2), moved
    CHECK(near(apply(svg::parse_transform("skewX(45)"), {0, 1}), {1, 1}, 1e-12));
    CHECK(near(apply(svg::parse_transform("skewY(45)"), {1, 0}), {1, 1}, 1e-12));
    CHECK(near(apply(svg::parse_transform("matrix(1 2 3 4 5 6)"), {1, 1}), {9, 12}));
    CHECK_THROWS_WITH(svg::parse_transform("rotate(1 2)"), "rotate() at character 1 takes 1 or 3 numbers, got 2");
    CHECK_THROWS_WITH(svg::parse_transform("scale(2"), "expected ')' at character 8, got the end");
}

TEST_CASE("strokes: caps and joins as Clipper offsets them", "[svg]") {
    const std::vector<svg::Chain> line = {{{0, 0}, {10, 0}}};
    auto total = [](const std::vector<svg::Chain>& loops) {
        double a = 0;
        for (const auto& l : loops) a += area(l);
        return std::abs(a);
    };
    svg::Stroke s;
    CHECK(total(svg::stroke_outline(line, s, 1e-4)) == Approx(11).epsilon(1e-12));  // square caps
    s.cap = svg::Stroke::Butt;
    CHECK(total(svg::stroke_outline(line, s, 1e-4)) == Approx(10).epsilon(1e-12));
    s.cap = svg::Stroke::Round;
    CHECK(total(svg::stroke_outline(line, s, 1e-4)) == Approx(10 + std::numbers::pi / 4).epsilon(1e-3));
    s.width = 0;
    CHECK(svg::stroke_outline(line, s, 1e-4).empty());
}
