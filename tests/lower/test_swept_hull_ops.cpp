// hull(), minkowski() and resize() of 2D shapes under a swept linear_extrude
// (a twist, an uneven scale, or a uniform scale over a sum or resize):
// done in the plane (interpreter/modules/flat_hull_ops.hpp) and swept like
// any polygon. Judged by closed forms — a twist keeps each section's area,
// so the volume is area × height — by point membership of the twisted
// section at a few heights (csg/membership.hpp, independent of the ray
// code), and by OpenSCAD 2021's STL volume for one scene.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "csg/membership.hpp"
#include "render/measure/measure.hpp"
#include "tests/lower/script_scene.hpp"

namespace {

using kerf::test::lowered;
constexpr double pi = std::numbers::pi;

void volume_is(const std::string& text, double exact, double rel = 0) {
    kerf::render::MeasureOptions o;
    o.resolution = 256;
    o.threads = 2;
    const auto m = kerf::render::measure(lowered(text), o);
    INFO(text << "\nvolume " << m.volume << " ± " << m.volume_error << ", exact " << exact);
    CHECK(std::abs(m.volume - exact) <= std::max(m.volume_error, rel * exact));
}

// The hull of the squares [-1, 1]² and [2.5, 3.5] × [-0.5, 0.5]: the
// first square and the trapezoid out to x = 3.5, area 4 + 3.75.
const std::string kHull = "hull() { square(2, center = true); translate([3, 0]) square(1, center = true); }";
constexpr double kHullArea = 7.75;

bool in_hull(glm::dvec2 p) {
    if (p.x <= -1 || p.x >= 3.5) return false;
    const double half = p.x <= 1 ? 1 : 1 - 0.5 * (p.x - 1) / 2.5;
    return std::abs(p.y) < half;
}

}  // namespace

TEST_CASE("a twisted hull of 2D shapes is the hull's polygon twisted", "[hull][sweep]") {
    const std::string text = "linear_extrude(height = 10, twist = 90) " + kHull;
    volume_is(text, kHullArea * 10);
    // Membership: at height z the section is the hull turned clockwise by
    // 90°·z/10, so a point is inside when turning it back lands in the hull.
    const kerf::csg::Scene s = lowered(text);
    int inside = 0;
    for (double z : {0.5, 2.5, 5.0, 7.5, 9.5})
        for (double x = -1.6; x <= 3.8; x += 0.3)
            for (double y = -3.8; y <= 3.8; y += 0.3) {
                const double t = pi / 2 * z / 10;  // the turn back: counter-clockwise
                const glm::dvec2 pre(std::cos(t) * x - std::sin(t) * y, std::sin(t) * x + std::cos(t) * y);
                INFO("z " << z << " point " << x << ", " << y);
                CHECK(kerf::csg::contains(s, {x, y, z}) == in_hull(pre));
                inside += in_hull(pre);
            }
    CHECK(inside > 100);
    // An uneven scale: sections (1 + τ) times wider, the area integral 1.5.
    volume_is("linear_extrude(height = 3, scale = [2, 1]) " + kHull, kHullArea * 3 * 1.5);
    // Circles of one radius: the stadium's polygon within the tolerance.
    volume_is("linear_extrude(height = 2, twist = 120) hull() { circle(1); translate([3, 0]) circle(1); }",
              2 * (pi + 6), 1e-3);
}

TEST_CASE("a twisted minkowski() of 2D shapes is the sum's region twisted", "[minkowski][sweep]") {
    // The rounded rectangle: (ab + r·perimeter + πr²) × height.
    volume_is("linear_extrude(height = 4, twist = 60) minkowski() { square([2, 3]); circle(0.5); }",
              4 * (6 + 0.5 * 10 + pi * 0.25), 1e-3);
    // A union summed part by part (two rounded squares apart: twice one).
    volume_is("linear_extrude(height = 2, twist = 45) minkowski() { union() { square(1); translate([4, 0]) square(1); } "
              "square(1, center = true); }",
              2 * 2 * 4);
    // One child: that child.
    volume_is("linear_extrude(height = 2, twist = 30) minkowski() square([1, 3]);", 6);
    // A uniform scale, which tapers only hulls: the area grows as (1 + τ)², ∫ = 7/3.
    volume_is("linear_extrude(height = 1, scale = 2) minkowski() { square(1); circle(1); }", 7.0 / 3 * (5 + pi), 1e-3);
}

TEST_CASE("a twisted resize() of 2D shapes is the resized shape twisted", "[resize][sweep]") {
    const std::string text = "linear_extrude(height = 2, twist = 90) resize([4, 6]) square([1, 2]);";
    volume_is(text, 2 * 24);
    const kerf::csg::Scene s = lowered(text);
    // At z = 1 the rectangle [0, 4] × [0, 6] is turned clockwise by 45°.
    for (double x = -0.93; x <= 8; x += 0.25)  // off the corners and edges
        for (double y = -3.91; y <= 4; y += 0.25) {
            const double t = pi / 4;
            const glm::dvec2 pre(std::cos(t) * x - std::sin(t) * y, std::sin(t) * x + std::cos(t) * y);
            INFO("point " << x << ", " << y);
            CHECK(kerf::csg::contains(s, {x, y, 1}) == (pre.x > 0 && pre.x < 4 && pre.y > 0 && pre.y < 6));
        }
    // A circle resized to an ellipse 4 × 2 (auto keeps the other axis's ratio).
    volume_is("linear_extrude(height = 3, twist = 200) resize([4, 2]) circle(1);", 3 * 2 * pi, 1e-3);
    volume_is("linear_extrude(height = 1, twist = 10) resize([6, 0], auto = true) square([2, 1]);", 6 * 3);
    volume_is("linear_extrude(height = 1, scale = 0.5) resize([2, 2]) square(1);", 4 * 7.0 / 12);
}

TEST_CASE("a twisted minkowski() matches OpenSCAD 2021's STL volume", "[minkowski][sweep]") {
    // `openscad -o m.stl` of this scene with slices = 100, 400, 1600 gives
    // STL volumes (divergence theorem) of 46.968710, 46.863814, 46.837249:
    // OpenSCAD's slices err as 1/slices, so their limit (Richardson, the
    // last two) is 46.8284 — the closed form 4·(6 + 5 + 2√2·0.5²) of the
    // rounded rectangle with an octagon (kerf honours $fn = 8) = 46.82843.
    volume_is("linear_extrude(height = 4, twist = 90) minkowski() { square([2, 3], center = true); "
              "circle(0.5, $fn = 8); }",
              46.8284, 1e-5);
}
