// rotate_extrude of 2D results that are not plain pieces on one side of
// the axis (docs/lowering.md, "Revolutions"): pieces crossing x = 0 whose
// crossing part a boolean removes (OpenSCAD checks the x sign on the 2D
// result, and so does kerf), and hull(), minkowski() and resize() done in
// the plane and revolved. Judged by closed forms (Pappus: a revolved
// region's volume is its area × 2π × its centroid's x; the bottle of
// Old/example017.scad as cylinder, half spheroid and ball) and by point
// membership (csg/membership.hpp, independent of the ray code).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "csg/membership.hpp"
#include "render/measure/measure.hpp"
#include "tests/lower/script_scene.hpp"

namespace {

using kerf::test::lowered;
constexpr double pi = std::numbers::pi;

kerf::render::Measurement measured(const kerf::csg::Scene& s) {
    kerf::render::MeasureOptions o;
    o.resolution = 256;
    o.threads = 2;
    return kerf::render::measure(s, o);
}

void volume_is(const std::string& text, double exact, double rel = 0) {
    const auto m = measured(lowered(text));
    INFO(text << "\nvolume " << m.volume << " ± " << m.volume_error << ", exact " << exact);
    CHECK(std::abs(m.volume - exact) <= std::max(m.volume_error, rel * exact));
}

// Points of the box [-w, w]² × [z0, z1] whose (ρ, z) lies farther than
// `band` from the region's boundary (`f` signed: < 0 inside, > 0 outside,
// its magnitude a distance or close to one) agree with the scene.
template <typename F>
int agrees(const kerf::csg::Scene& s, double w, double z0, double z1, double band, F&& f) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    int inside = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 p((2 * u(rng) - 1) * w, (2 * u(rng) - 1) * w, z0 + (z1 - z0) * u(rng));
        const double d = f(std::hypot(p.x, p.y), p.z);
        if (std::abs(d) < band) continue;
        INFO("point " << p.x << ", " << p.y << ", " << p.z << ": " << d);
        CHECK(kerf::csg::contains(s, p) == (d < 0));
        inside += d < 0;
    }
    return inside;
}

}  // namespace

TEST_CASE("the bottle of Old/example017.scad: pieces cross the axis, the result does not", "[revolve]") {
    // Its circles reach x = -25 and x = -12.5 before the intersections cut
    // them to x >= 0 (kerf used to check each piece: "range is -25.00 ->
    // 25.00"). The result is a cylinder ρ < 25, z < 68, the upper half of
    // the spheroid ρ²/25² + (z - 68)²/17.5² < 1 and the ball of radius 12.5
    // about z = 93.
    const std::string text = "r = 25; h = 68;\n"
                             "rotate_extrude() {\n"
                             "  square([r, h]);\n"
                             "  translate([0, h]) intersection() { square([r, r]); scale([1, 0.7]) circle(r); }\n"
                             "  translate([0, h + r]) intersection() { translate([0, -r / 2]) square([r / 2, r]); "
                             "circle(r / 2); }\n"
                             "}\n";
    const kerf::csg::Scene s = lowered(text);
    const int inside = agrees(s, 30, -5, 110, 0.05, [](double rho, double z) {
        const double cylinder = std::max({rho - 25, -z, z - 68});
        const double cap = std::max(68 - z, 25 * (std::hypot(rho / 25, (z - 68) / 17.5) - 1));
        const double ball = std::hypot(rho, z - 93) - 12.5;
        return std::min({cylinder, cap, ball});
    });
    CHECK(inside > 1000);
    // The volume: π·25²·68, the half spheroid and the ball less their
    // overlap, ∫ π·max(ρ₁², ρ₂²) dz over the cap (ρ₁² = 625 − z²/0.49 and
    // ρ₂² = 156.25 − (z − 25)² cross at z = 16.3264 above the cylinder):
    // 163938.987. OpenSCAD 2021.01's STL of the same profile
    // (`openscad -D '$fn=720' -o b.stl`, volume summed over its triangles):
    // 163936.31; at its default facets 162433.40. kerf measure
    // --resolution 1024: 163936.4 ± 23.
    const double zc = (50 - std::sqrt(2500 - 4 * (1 - 1 / 0.49) * (1250 - 156.25))) / (2 * (1 - 1 / 0.49));
    REQUIRE(zc == Approx(16.326388291));
    auto F1 = [](double z) { return 625 * z - z * z * z / (3 * 0.49); };
    auto F2 = [](double z) { return 156.25 * z - (z - 25) * (z - 25) * (z - 25) / 3; };
    const double exact = pi * 625 * 68 + pi * (F1(zc) - F1(0)) + pi * (F2(37.5) - F2(zc));
    CHECK(exact == Approx(163938.9866).epsilon(1e-9));
    const auto m = measured(s);
    INFO("volume " << m.volume << " ± " << m.volume_error);
    CHECK(std::abs(m.volume - exact) <= m.volume_error);
}

TEST_CASE("a boolean that removes what crosses the axis revolves its result", "[revolve]") {
    // The square [-5, 5] × [0, 10] less its half at x < 0: the cylinder ρ < 5.
    const kerf::csg::Scene tube = lowered(
        "rotate_extrude() difference() { translate([-5, 0]) square([10, 10]); translate([-6, -1]) square([6, 12]); }");
    CHECK(agrees(tube, 6, -1, 11, 1e-9, [](double rho, double z) { return std::max({rho - 5, -z, z - 10}); }) > 1000);
    volume_is("rotate_extrude() difference() { translate([-5, 0]) square([10, 10]); translate([-6, -1]) square([6, "
              "12]); }",
              pi * 25 * 10);
    // A result at x <= 0 is revolved where it lies (mirrored), the half at
    // x > 0 removed first: the cylinder ρ < 10, 0 < z < 5.
    const kerf::csg::Scene left = lowered("rotate_extrude() difference() { translate([-10, 0]) square([15, 5]); "
                                          "translate([0, -1]) square([6, 7]); }");
    CHECK(agrees(left, 11, -1, 6, 1e-9, [](double rho, double z) { return std::max({rho - 10, -z, z - 5}); }) > 1000);
    // A circle about a point across the axis (a horn torus's profile cut
    // in half by an intersection): the ball ρ² + z² < 4.
    const kerf::csg::Scene ball =
        lowered("rotate_extrude() intersection() { circle(2); translate([0, -3]) square([3, 6]); }");
    CHECK(agrees(ball, 2.5, -2.5, 2.5, 1e-3, [](double rho, double z) { return std::hypot(rho, z) - 2; }) > 300);
    volume_is("rotate_extrude() intersection() { circle(2); translate([0, -3]) square([3, 6]); }", 4 * pi * 8 / 3,
              1e-3);
}

TEST_CASE("a piece wholly across the axis contributes nothing to the revolution", "[revolve]") {
    // The circle about (-2, 2) is not in the half-plane the revolution
    // sees: subtracting it leaves the whole cylinder ρ < 4, 0 < z < 4 (its
    // torus would carve a ring at ρ = 2).
    const kerf::csg::Scene s =
        lowered("rotate_extrude() difference() { square([4, 4]); translate([-2, 2]) circle(1); }");
    CHECK(agrees(s, 5, -1, 5, 1e-9, [](double rho, double z) { return std::max({rho - 4, -z, z - 4}); }) > 1000);
    CHECK(kerf::csg::contains(s, {2, 0, 2}));
    // Intersected with it, nothing is left.
    CHECK(lowered("rotate_extrude() intersection() { square([4, 4]); translate([-2, 2]) circle(1); }").root ==
          kerf::csg::kNone);
}

TEST_CASE("hull, minkowski and resize of 2D shapes revolve (Pappus)", "[revolve][hull]") {
    // The hull of two unit circles about (3, 0) and (6, 2): a stadium of
    // area π + 2·√13 (the segment's length) and centroid x 4.5.
    const std::string hull = "rotate_extrude() hull() { translate([3, 0]) circle(1); translate([6, 2]) circle(1); }";
    // OpenSCAD 2021.01, `openscad -D '$fn=720' -o x.stl`: 292.7100.
    volume_is(hull, (pi + 2 * std::sqrt(13.0)) * 2 * pi * 4.5, 1e-4);
    const kerf::csg::Scene s = lowered(hull);
    CHECK(agrees(s, 7.5, -1.5, 3.5, 2e-3, [](double rho, double z) {
              // The distance to the segment between the centres, less 1.
              const glm::dvec2 a(3, 0), b(6, 2), p(rho, z);
              const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
              return glm::length(p - (a + t * (b - a))) - 1;
          }) > 200);
    // The rectangle [0, 2] × [0, 1] grown by a disc of radius 0.5, moved to
    // x = 3: area 2 + 0.5·6 + π/4, centroid x 4 (OpenSCAD: 145.3995).
    volume_is("rotate_extrude() translate([3, 0]) minkowski() { square([2, 1]); circle(0.5); }",
              (2 + 3 + pi / 4) * 2 * pi * 4, 1e-4);
    // A resize is the scale it applies: [2, 4] × [0, 4], the tube 48π (OpenSCAD: 150.7945).
    volume_is("rotate_extrude() translate([2, 0]) resize([2, 4]) square(1);", 48 * pi);
    // The x sign is checked on the hull too.
    REQUIRE_THROWS_WITH(lowered("rotate_extrude() hull() { translate([-1, 0]) square(1); translate([2, 0]) square(1); }"),
                        Catch::Contains("same X coordinate sign (range is -1.00 -> 3.00)"));
}
