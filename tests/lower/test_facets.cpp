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

namespace {
csg::Scene lowered_in(FacetMode mode, const std::string& text) {
    auto f = std::make_shared<SourceFile>();
    f->path = "test.scad";
    f->text = text;
    EvalOptions opt;
    opt.facets = mode;
    return lower_to_csg(evaluate_source(f, opt).graph);
}

// The polar point at radius r, angle a (degrees), height z.
glm::dvec3 polar(double r, double a, double z) { return {r * std::cos(a * M_PI / 180), r * std::sin(a * M_PI / 180), z}; }
}  // namespace

TEST_CASE("facets exact ignores every $fn: the hex nut is round") {
    const std::string nut = "cylinder(h = 3, r = 5, $fn = 6);";
    const csg::Scene exact = lowered_in(FacetMode::Exact, nut), faceted = lowered_in(FacetMode::Auto, nut);
    // Along a ray at 30° (through the middle of a hexagon side, 4.33 from the
    // axis), the exact cylinder is entered at 5 and the hexagon at 4.33.
    for (double r : {4.4, 4.7, 4.95}) {
        CHECK(csg::contains(exact, polar(r, 30, 1.5)));
        CHECK_FALSE(csg::contains(faceted, polar(r, 30, 1.5)));
    }
    CHECK_FALSE(csg::contains(exact, polar(5.05, 30, 1.5)));
    const csg::Scene ball = lowered_in(FacetMode::Exact, "sphere(1, $fn = 6);");
    CHECK(csg::contains(ball, {0, 0, 0.95}));  // OpenSCAD's cap is at z = 0.866
}

// --facets openscad against OpenSCAD 2021's own export: `echo 'CALL' >
// one.scad; openscad -o one.stl one.scad`, the box of the STL's vertices
// (6 significant digits). Meshes and prisms have exact boxes (the box of
// their corners), so the boxes must agree to the STL's rounding.
TEST_CASE("facets openscad places the vertices where OpenSCAD 2021 does") {
    struct Case {
        const char* scad;
        glm::dvec3 lo, hi;
    };
    const Case cases[] = {
        {"sphere(r = 1, $fn = 6);", {-1, -0.866025, -0.866025}, {1, 0.866025, 0.866025}},
        {"sphere(5);", {-4.90393, -4.90393, -4.90393}, {4.90393, 4.90393, 4.90393}},
        {"sphere(r = 3, $fa = 20, $fs = 0.5);", {-3, -2.95442, -2.95442}, {3, 2.95442, 2.95442}},
        {"cylinder(h = 4, r1 = 0, r2 = 2, $fn = 7);", {-1.80194, -1.94986, 0}, {2, 1.94986, 4}},
        {"cylinder(h = 4, r1 = 2, r2 = 0);", {-1.80194, -1.94986, 0}, {2, 1.94986, 4}},
        {"linear_extrude(2) circle(3);", {-3, -2.85317, 0}, {3, 2.85317, 2}},
        {"linear_extrude(1) offset(r = 1, $fn = 8) square(2);", {-1, -1, 0}, {3, 3, 1}},
    };
    for (const Case& c : cases) {
        INFO(c.scad);
        const csg::Aabb b = lowered_in(FacetMode::OpenScad, c.scad).bounds();
        for (int k = 0; k < 3; ++k) {
            CHECK(b.lo[k] == Approx(c.lo[k]).margin(1e-5));
            CHECK(b.hi[k] == Approx(c.hi[k]).margin(1e-5));
        }
    }
    // sphere($fn = 6): 3 rings at 30°, 90°, 150° from the pole, 6 vertices
    // each, the first on +x; OpenSCAD's OFF export lists these 18 (some here).
    const csg::Scene ball = lowered_in(FacetMode::OpenScad, "sphere(1, $fn = 6);");
    REQUIRE(ball.meshes.size() == 1);
    CHECK(ball.meshes[0].points.size() == 18);
    const glm::dvec3 off[] = {{0.5, 0, 0.866025}, {0.25, 0.433013, 0.866025}, {1, 0, 0}, {0.5, 0.866025, 0},
                              {-1, 0, 0}, {-0.25, -0.433013, -0.866025}};
    for (const glm::dvec3& v : off) {
        double nearest = 1e9;
        for (const auto& p : ball.meshes[0].points) nearest = std::min(nearest, glm::distance(glm::dvec3(p), v));
        INFO(v.x << ", " << v.y << ", " << v.z);
        CHECK(nearest < 1e-6);
    }
}

// rotate_extrude in OpenSCAD 2021's steps: a full turn's meridians start on
// −x (OpenSCAD's OFF of `rotate_extrude($fn = 7) translate([2, 0])
// square(1);` has the vertex (-3, 0, 0), none at +3), a partial one's on +x
// (`rotate_extrude(angle = 90, $fn = 8) ...`: 2 steps, vertices at 0°, 45°,
// 90°, e.g. (2.12132, 2.12132, 1)); between two meridians the faces are flat,
// so halfway round the ring reaches only r·cos(half the step).
TEST_CASE("facets openscad revolves in the steps of OpenSCAD") {
    const csg::Scene ring = lowered_in(FacetMode::OpenScad, "rotate_extrude($fn = 7) translate([2, 0]) square(1);");
    const double half = 180.0 / 7, c = std::cos(half * M_PI / 180);
    for (int k = 0; k < 7; ++k) {
        // 0.05° past the meridian (on it, the point lies on two pieces' shared face).
        const double meridian = 180 - k * 360.0 / 7, mid = meridian - half, near = meridian + 0.05;
        INFO("meridian " << meridian);
        CHECK(csg::contains(ring, polar(2.99, near, 0.5)));
        CHECK_FALSE(csg::contains(ring, polar(3.01, near, 0.5)));
        CHECK(csg::contains(ring, polar(2.01, near, 0.5)));
        CHECK_FALSE(csg::contains(ring, polar(1.99, near, 0.5)));
        CHECK(csg::contains(ring, polar(3 * c * 0.999, mid, 0.5)));
        CHECK_FALSE(csg::contains(ring, polar(3 * c * 1.001, mid, 0.5)));
        CHECK(csg::contains(ring, polar(2 * c * 1.001, mid, 0.5)));
        CHECK_FALSE(csg::contains(ring, polar(2 * c * 0.999, mid, 0.5)));
    }
    const csg::Scene part = lowered_in(FacetMode::OpenScad, "rotate_extrude(angle = 90, $fn = 8) translate([2, 0]) square(1);");
    const double c8 = std::cos(22.5 * M_PI / 180);
    for (double mid : {22.5, 67.5}) {
        CHECK(csg::contains(part, polar(3 * c8 * 0.999, mid, 0.5)));
        CHECK_FALSE(csg::contains(part, polar(3 * c8 * 1.001, mid, 0.5)));
    }
    CHECK(csg::contains(part, polar(2.99, 45, 0.5)));
    CHECK_FALSE(csg::contains(part, polar(2.5, -1, 0.5)));
    CHECK_FALSE(csg::contains(part, polar(2.5, 91, 0.5)));
}
