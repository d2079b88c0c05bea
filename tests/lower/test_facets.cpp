// An explicit $fn from 3 to 12 on circle or cylinder is OpenSCAD's regular
// polygon (docs/openscad.md, "Facets"): the hex nut is hexagonal. Checked
// against OpenSCAD 2021's own STL bounds (`echo 'CALL' > one.scad;
// openscad -o one.stl one.scad`, the vertices' box) and point by point
// against the regular polygon's closed form.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "csg/membership.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {
// Inside the regular n-gon of circumradius r with a vertex on +x.
bool in_ngon(int n, double r, double x, double y) {
    const double apothem = r * std::cos(M_PI / n);
    for (int k = 0; k < n; ++k) {
        const double a = M_PI * (2 * k + 1) / n;  // the outward normal of edge k
        if (x * std::cos(a) + y * std::sin(a) > apothem) return false;
    }
    return true;
}
}  // namespace

TEST_CASE("an explicit $fn from 3 to 12 makes OpenSCAD's regular polygon") {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(-6, 6);
    const csg::Scene nut = test::lowered("cylinder(h = 3, r = 5, $fn = 6);");
    // OpenSCAD: [-5, -4.33013, 0] .. [5, 4.33013, 3].
    CHECK(nut.bounds().lo.y == Approx(-4.33013).margin(1e-5));
    CHECK(nut.bounds().hi.x == Approx(5).margin(1e-9));
    const csg::Scene oct = test::lowered("linear_extrude(2) circle(3, $fn = 8);");
    const csg::Scene round = test::lowered("cylinder(h = 3, r = 5, $fn = 64);");  // beyond 12: exact
    int corner = 0;
    for (int i = 0; i < 20000; ++i) {
        const double x = u(rng), y = u(rng);
        INFO(x << ", " << y);
        REQUIRE(csg::contains(nut, {x, y, 1.5}) == in_ngon(6, 5, x, y));
        REQUIRE(csg::contains(oct, {x, y, 1}) == in_ngon(8, 3, x, y));
        REQUIRE(csg::contains(round, {x, y, 1.5}) == (std::hypot(x, y) < 5));
        corner += std::hypot(x, y) < 5 && !in_ngon(6, 5, x, y);
    }
    CHECK(corner > 100);  // points where the hexagon and the circle differ were tried
    // A frustum: OpenSCAD [-2.42705, -2.85317, 0] .. [3, 2.85317, 4].
    const csg::Scene frustum = test::lowered("cylinder(h = 4, r1 = 3, r2 = 1.5, $fn = 5);");
    CHECK(frustum.bounds().lo.x == Approx(-2.42705).margin(1e-5));
    CHECK(frustum.bounds().hi.y == Approx(2.85317).margin(1e-5));
    CHECK(csg::contains(frustum, {2.9, 0, 0.05}));
    CHECK_FALSE(csg::contains(frustum, {2.9, 0, 3.9}));
    CHECK(csg::contains(frustum, {1.45, 0, 3.9}));
}
