// The modules of stdlib/ evaluated through `use <...>` (found on the stdlib
// search path), checked against their geometric definitions: primitive
// kinds and counts, parameters and world placement of every leaf.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/interpreter/eval_helpers.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::PrimKind;

namespace {

std::vector<Leaf> stdlib_leaves(const std::string& body) {
    return leaves_of("use <shapes.sdl>\nuse <patterns.sdl>\n" + body);
}

glm::dvec3 origin_of(const Leaf& l) { return glm::dvec3(l.world * glm::dvec4(0, 0, 0, 1)); }
glm::dvec3 axis_of(const Leaf& l) { return glm::dvec3(l.world * glm::dvec4(0, 0, 1, 0)); }

std::size_t count(const std::vector<Leaf>& ls, PrimKind k) {
    return static_cast<std::size_t>(std::count_if(ls.begin(), ls.end(), [k](const Leaf& l) { return l.prim == k; }));
}

bool near(glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-12; }

}  // namespace

TEST_CASE("stdlib: tube is a cylinder minus a longer bore", "[stdlib]") {
    auto g = run("use <shapes.sdl>\ntube(h = 2, r_outer = 1, r_inner = 0.6);").graph;
    CHECK(shape(g, g.root).find("D(cylinder,T(cylinder))") != std::string::npos);
    auto ls = leaves(g);
    REQUIRE(ls.size() == 2);
    // Outer: z in [0, 2], radius 1 at both ends.
    CHECK(ls[0].p[0] == 0);
    CHECK(ls[0].p[1] == 2);
    CHECK(ls[0].p[2] == 1);
    CHECK(ls[0].p[3] == 1);
    // Bore: radius 0.6, spanning beyond both caps in world space.
    CHECK(ls[1].p[2] == 0.6);
    double z0 = (ls[1].world * glm::dvec4(0, 0, ls[1].p[0], 1)).z;
    double z1 = (ls[1].world * glm::dvec4(0, 0, ls[1].p[1], 1)).z;
    CHECK(z0 < 0);
    CHECK(z1 > 2);

    auto centred = stdlib_leaves("tube(h = 2, r_outer = 1, r_inner = 0.5, center = true);");
    REQUIRE(centred.size() == 2);
    CHECK(centred[0].p[0] == -1);
    CHECK(centred[0].p[1] == 1);
    CHECK((centred[1].world * glm::dvec4(0, 0, centred[1].p[0], 1)).z < -1);
    CHECK((centred[1].world * glm::dvec4(0, 0, centred[1].p[1], 1)).z > 1);

    auto solid = stdlib_leaves("tube(h = 1, r_outer = 2, r_inner = 0);");
    REQUIRE(solid.size() == 1);
    CHECK(solid[0].prim == PrimKind::Cylinder);

    CHECK_THAT(error_of("use <shapes.sdl>\ntube(h = 1, r_outer = 1, r_inner = 1);"),
               Catch::Contains("tube: need 0 <= r_inner < r_outer"));
}

TEST_CASE("stdlib: rounded_box is 3 slabs, 12 edge cylinders and 8 corner spheres", "[stdlib]") {
    const glm::dvec3 s(4, 3, 2);
    const double r = 0.5;
    auto ls = stdlib_leaves("rounded_box([4, 3, 2], radius = 0.5);");
    REQUIRE(ls.size() == 23);
    REQUIRE(count(ls, PrimKind::Box) == 3);
    REQUIRE(count(ls, PrimKind::Sphere) == 8);
    REQUIRE(count(ls, PrimKind::Cylinder) == 12);

    // The union's extent: every slab lies within [0, s] and each touches
    // two opposite faces; together they reach all six faces.
    glm::dvec3 lo(1e9), hi(-1e9);
    for (const Leaf& l : ls) {
        if (l.prim != PrimKind::Box) continue;
        glm::dvec3 a = glm::dvec3(l.world * glm::dvec4(l.p[0], l.p[1], l.p[2], 1));
        glm::dvec3 b = glm::dvec3(l.world * glm::dvec4(l.p[3], l.p[4], l.p[5], 1));
        lo = glm::min(lo, glm::min(a, b));
        hi = glm::max(hi, glm::max(a, b));
        // Shrunk by r on exactly two axes.
        int full = 0;
        for (int k = 0; k < 3; ++k) {
            double w = std::abs(b[k] - a[k]);
            if (w == s[k]) ++full;
            else CHECK(w == Approx(s[k] - 2 * r));
        }
        CHECK(full == 1);
    }
    CHECK(near(lo, glm::dvec3(0)));
    CHECK(near(hi, s));

    // Corner spheres of radius r centred r inside each corner.
    std::vector<glm::dvec3> corners;
    for (const Leaf& l : ls)
        if (l.prim == PrimKind::Sphere) {
            CHECK(l.p[0] == r);
            corners.push_back(origin_of(l));
        }
    for (double x : {r, s.x - r})
        for (double y : {r, s.y - r})
            for (double z : {r, s.z - r})
                CHECK(std::any_of(corners.begin(), corners.end(),
                                  [&](glm::dvec3 c) { return near(c, glm::dvec3(x, y, z)); }));

    // Edge cylinders: radius r, 4 along each axis, each spanning the box
    // length minus 2r, starting r in from the face.
    int per_axis[3] = {0, 0, 0};
    for (const Leaf& l : ls) {
        if (l.prim != PrimKind::Cylinder) continue;
        CHECK(l.p[2] == r);
        CHECK(l.p[3] == r);
        glm::dvec3 a = glm::dvec3(l.world * glm::dvec4(0, 0, l.p[0], 1));
        glm::dvec3 b = glm::dvec3(l.world * glm::dvec4(0, 0, l.p[1], 1));
        glm::dvec3 d = b - a;
        int axis = std::abs(d.x) > 1e-9 ? 0 : std::abs(d.y) > 1e-9 ? 1 : 2;
        ++per_axis[axis];
        CHECK(d[axis] == Approx(s[axis] - 2 * r));
        CHECK(std::min(a[axis], b[axis]) == Approx(r));
        for (int k = 0; k < 3; ++k)
            if (k != axis) CHECK((std::abs(a[k] - r) < 1e-12 || std::abs(a[k] - (s[k] - r)) < 1e-12));
    }
    CHECK(per_axis[0] == 4);
    CHECK(per_axis[1] == 4);
    CHECK(per_axis[2] == 4);
}

TEST_CASE("stdlib: rounded_box centring, radius 0 and bad radius", "[stdlib]") {
    auto ls = stdlib_leaves("rounded_box(2, radius = 0.25, center = true);");
    REQUIRE(ls.size() == 23);
    for (const Leaf& l : ls) {
        glm::dvec3 o = origin_of(l);
        if (l.prim == PrimKind::Sphere) CHECK(near(glm::abs(o), glm::dvec3(0.75)));
    }
    auto plain = stdlib_leaves("rounded_box([1, 2, 3], radius = 0);");
    REQUIRE(plain.size() == 1);
    CHECK(plain[0].prim == PrimKind::Box);
    CHECK_THAT(error_of("use <shapes.sdl>\nrounded_box([1, 2, 3], radius = 0.5);"),
               Catch::Contains("rounded_box: need 0 <= radius < min(size) / 2"));
}

TEST_CASE("stdlib: regular_prism is a cylinder minus the n half-spaces beyond its sides", "[stdlib]") {
    // The geometry itself (points inside and outside the n-gon) is checked
    // by point membership after lowering: tests/lower/test_stdlib_solids.cpp.
    const int n = 6;
    const double r = 2, h = 3;
    auto g = run("use <shapes.sdl>\nregular_prism(6, 2, 3);").graph;
    auto ls = leaves(g);
    REQUIRE(ls.size() == n + 1);
    CHECK(shape(g, g.root).find("D(cylinder,") != std::string::npos);
    CHECK(ls[0].prim == PrimKind::Cylinder);
    CHECK(ls[0].p[1] - ls[0].p[0] == h);
    CHECK(ls[0].p[2] == r);
    const double apothem = r * std::cos(std::numbers::pi / n);
    for (int i = 1; i <= n; ++i) {
        REQUIRE(ls[i].prim == PrimKind::Plane);
        // The half-space {dot(m, x) <= -apothem} with m pointing at the
        // centre from an edge midpoint: everything beyond that edge.
        glm::dvec3 m = glm::dvec3(ls[i].world * glm::dvec4(ls[i].p[0], ls[i].p[1], ls[i].p[2], 0));
        CHECK(glm::length(m) == Approx(1));
        CHECK(m.z == Approx(0).margin(1e-15));
        CHECK(ls[i].p[3] == Approx(-apothem));
        double angle = std::atan2(-m.y, -m.x) * 180 / std::numbers::pi;
        double expected = (i - 1 + 0.5) * 360.0 / n;
        if (expected > 180) expected -= 360;
        CHECK(angle == Approx(expected));
    }
    CHECK_THAT(error_of("use <shapes.sdl>\nregular_prism(2.5, 1, 1);"),
               Catch::Contains("regular_prism: n must be an integer >= 3"));
}

TEST_CASE("stdlib: linear and grid patterns translate copies of the children", "[stdlib]") {
    auto ls = stdlib_leaves("linear_pattern(4, [1.5, 0, 2]) { sphere(0.2); cube(0.1); }");
    REQUIRE(ls.size() == 8);
    CHECK(count(ls, PrimKind::Sphere) == 4);
    std::vector<glm::dvec3> at;
    for (const Leaf& l : ls)
        if (l.prim == PrimKind::Sphere) at.push_back(origin_of(l));
    for (int k = 0; k < 4; ++k)
        CHECK(std::any_of(at.begin(), at.end(), [&](glm::dvec3 o) { return near(o, glm::dvec3(1.5 * k, 0, 2 * k)); }));

    auto grid = stdlib_leaves("grid_pattern(3, 2, [2, 5]) sphere(1);");
    REQUIRE(grid.size() == 6);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j)
            CHECK(std::any_of(grid.begin(), grid.end(),
                              [&](const Leaf& l) { return near(origin_of(l), glm::dvec3(2 * i, 5 * j, 0)); }));
}

TEST_CASE("stdlib: polar_pattern rotates copies about the axis", "[stdlib]") {
    auto ls = stdlib_leaves("polar_pattern(4) translate([3, 0, 0]) sphere(0.5);");
    REQUIRE(ls.size() == 4);
    for (glm::dvec3 p : {glm::dvec3(3, 0, 0), glm::dvec3(0, 3, 0), glm::dvec3(-3, 0, 0), glm::dvec3(0, -3, 0)})
        CHECK(std::any_of(ls.begin(), ls.end(), [&](const Leaf& l) { return glm::length(origin_of(l) - p) < 1e-9; }));

    // A partial arc: first copy at 0°, last at `angle`.
    auto arc = stdlib_leaves("polar_pattern(3, angle = 90) translate([1, 0, 0]) sphere(0.1);");
    REQUIRE(arc.size() == 3);
    for (double deg : {0.0, 45.0, 90.0}) {
        double a = deg * std::numbers::pi / 180;
        glm::dvec3 p(std::cos(a), std::sin(a), 0);
        CHECK(std::any_of(arc.begin(), arc.end(), [&](const Leaf& l) { return glm::length(origin_of(l) - p) < 1e-9; }));
    }

    // About the X axis: a cylinder's axis turns in the YZ plane.
    auto tilted = stdlib_leaves("polar_pattern(2, axis = [1, 0, 0]) cylinder(h = 1, r = 0.1);");
    REQUIRE(tilted.size() == 2);
    CHECK(std::any_of(tilted.begin(), tilted.end(),
                      [](const Leaf& l) { return glm::length(axis_of(l) - glm::dvec3(0, 0, -1)) < 1e-9; }));
}

TEST_CASE("stdlib: mirror_copy adds the mirror image", "[stdlib]") {
    auto ls = stdlib_leaves("mirror_copy([1, 0, 0]) translate([2, 1, 0]) sphere(0.5);");
    REQUIRE(ls.size() == 2);
    CHECK(std::any_of(ls.begin(), ls.end(), [](const Leaf& l) { return near(origin_of(l), glm::dvec3(2, 1, 0)); }));
    CHECK(std::any_of(ls.begin(), ls.end(), [](const Leaf& l) { return near(origin_of(l), glm::dvec3(-2, 1, 0)); }));
}
