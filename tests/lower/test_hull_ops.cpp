// hull(), minkowski() and resize() (docs/lowering.md, "Hull, Minkowski,
// resize"): the lowered solids' volumes and bounds, measured by the ray
// grids of render/measure, against closed forms; the exact cases built
// from exact leaves only, never tessellated.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/measure/measure.hpp"
#include "tests/lower/script_scene.hpp"

namespace {

using kerf::test::lowered;
constexpr double pi = std::numbers::pi;

kerf::render::Measurement measured(const std::string& text, int resolution = 256) {
    kerf::render::MeasureOptions o;
    o.resolution = resolution;
    o.threads = 2;
    return kerf::render::measure(lowered(text), o);
}

void volume_is(const std::string& text, double exact, double rel = 0) {
    const auto m = measured(text);
    INFO(text << "\nvolume " << m.volume << " ± " << m.volume_error << ", exact " << exact);
    CHECK(std::abs(m.volume - exact) <= std::max(m.volume_error, rel * exact));
}

// Leaves by kind, and the largest mesh's point count.
std::map<kerf::csg::PrimKind, int> kinds(const kerf::csg::Scene& s, std::size_t* mesh_points = nullptr) {
    std::map<kerf::csg::PrimKind, int> k;
    for (const auto& l : s.leaves) ++k[l.kind];
    if (mesh_points) {
        *mesh_points = 0;
        for (const auto& m : s.meshes) *mesh_points = std::max(*mesh_points, m.points.size());
    }
    return k;
}

// Rounded box a×b×c grown by r: the box, its faces moved out, quarter
// cylinders along the edges, eighth balls at the corners.
double rounded_box(double a, double b, double c, double r) {
    return a * b * c + 2 * r * (a * b + b * c + c * a) + pi * r * r * (a + b + c) + 4.0 / 3 * pi * r * r * r;
}

// The hull of spheres r1 at the origin and r2 at distance d (r1 >= r2):
// the big ball up to its tangent circle, the frustum, the small ball's cap.
double two_ball_hull(double r1, double r2, double d) {
    const double s = (r1 - r2) / d, c = std::sqrt(1 - s * s);
    const double h0 = r1 * s, h1 = r2 * s;
    const double big = pi * (r1 * r1 * h0 - h0 * h0 * h0 / 3 + 2 * r1 * r1 * r1 / 3);
    const double small = pi * (2 * r2 * r2 * r2 / 3 - r2 * r2 * h1 + h1 * h1 * h1 / 3);
    const double len = d + h1 - h0, R = r1 * c, rr = r2 * c;
    return big + small + pi * len / 3 * (R * R + R * rr + rr * rr);
}

}  // namespace

TEST_CASE("hull() of boxes and polyhedron points is the exact polytope", "[hull]") {
    volume_is("hull() { cube(1); translate([3, 0, 0]) cube(1); }", 4);
    // A tetrahedron's corners plus points inside it: the corners' volume 1/6 · 2·3·4.
    volume_is("hull() { polyhedron([[0,0,0],[2,0,0],[0,3,0],[0,0,4],[0.1,0.1,0.1],[0.5,0.5,0.5]],"
              " [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]); }",
              4);
    const auto s = lowered("hull() { cube(1); translate([3, 0, 0]) rotate([0, 0, 45]) cube(1); }");
    std::size_t points = 0;
    const auto k = kinds(s, &points);
    CHECK(k.size() == 1);
    CHECK(k.at(kerf::csg::PrimKind::Mesh) == 1);
    CHECK(points <= 16);
}

TEST_CASE("a polyhedron read by hull() is not copied, yet a resize or a lone minkowski child still draws it",
          "[hull]") {
    // The corner tetrahedron 2·3·4/6 = 4; lowering leaves out a mesh only a
    // hull or sum consumes (lower/geometry_ops.cpp), never one drawn.
    const std::string tetra = "polyhedron([[0,0,0],[2,0,0],[0,3,0],[0,0,4]], [[0,1,2],[0,3,1],[0,2,3],[1,3,2]])";
    volume_is("hull() { resize([4, 0, 0]) " + tetra + "; }", 8);             // resize reads the mesh's box
    volume_is("minkowski() " + tetra + ";", 4);                              // one child: drawn as it is
    volume_is("hull() " + tetra + "; translate([5, 0, 0]) " + tetra + ";", 8);  // one consumed, one drawn
    volume_is("hull() { hull() " + tetra + "; translate([0, 0, 4]) " + tetra + "; }",
              4 + 3 * 4);  // the tetrahedron swept up by 4: its volume plus its shadow's area × 4
}

TEST_CASE("the hull of equal spheres is their centres' hull grown exactly", "[hull]") {
    // Two balls: a capsule, built from two spheres and a cylinder.
    const std::string capsule = "hull() { sphere(1); translate([4, 0, 0]) sphere(1); }";
    volume_is(capsule, pi * 4 + 4.0 / 3 * pi);
    const auto k = kinds(lowered(capsule));
    CHECK(k.at(kerf::csg::PrimKind::Sphere) == 2);
    CHECK(k.at(kerf::csg::PrimKind::Cylinder) == 1);
    CHECK(k.count(kerf::csg::PrimKind::Mesh) == 0);
    // Eight balls at a box's corners: the rounded box; three in a plane: a rounded triangle slab.
    volume_is("hull() for (x = [0, 2], y = [0, 3], z = [0, 4]) translate([x, y, z]) sphere(0.5);",
              rounded_box(2, 3, 4, 0.5));
    // Triangle (legs 3, 4) ⊕ ball: slab 2r·A + perimeter half-cylinders πr²·P + ball.
    const double r = 0.5, area = 6, perimeter = 12;
    volume_is("hull() { sphere(0.5); translate([3, 0, 0]) sphere(0.5); translate([0, 4, 0]) sphere(0.5); }",
              2 * r * area + pi * r * r * perimeter / 2 + 4.0 / 3 * pi * r * r * r);
}

TEST_CASE("the hull of unequal spheres is tessellated within the curve tolerance", "[hull]") {
    volume_is("hull() { sphere(2); translate([5, 0, 0]) sphere(1); }", two_ball_hull(2, 1, 5), 1e-3);
    const auto k = kinds(lowered("hull() { sphere(2); translate([5, 0, 0]) sphere(1); }"));
    CHECK(k.at(kerf::csg::PrimKind::Mesh) == 1);
    // A cylinder's hull with a point: the cylinder and a cone to the point.
    volume_is("hull() { cylinder(h = 2, r = 1); translate([0, 0, 5]) cube(0.0001, center = true); }",
              pi * 2 + pi * 3 / 3, 1e-3);
}

TEST_CASE("minkowski() of a box and a sphere is the exact rounded box", "[minkowski]") {
    const std::string text = "minkowski() { cube([2, 3, 4]); sphere(0.5); }";
    volume_is(text, rounded_box(2, 3, 4, 0.5));
    std::size_t points = 0;
    const auto k = kinds(lowered(text), &points);
    CHECK(k.at(kerf::csg::PrimKind::Sphere) == 8);
    CHECK(k.at(kerf::csg::PrimKind::Cylinder) == 12);
    CHECK(points <= 8);  // the box and its face prisms: nothing tessellated
    const auto m = measured(text);
    CHECK(m.bounds.lo.x == Approx(-0.5).margin(1e-6));
    CHECK(m.bounds.hi.z == Approx(4.5).margin(1e-6));
    // Rotated and scaled (a similarity keeps the ball a ball), and in the other order.
    volume_is("minkowski() { sphere(0.25); scale(2) rotate([10, 20, 30]) cube([1, 1.5, 2]); }",
              rounded_box(2, 3, 4, 0.25));
}

TEST_CASE("minkowski() of convex polytopes, of unions and with one child", "[minkowski]") {
    volume_is("minkowski() { cube([1, 2, 3]); cube([2, 1, 1]); }", 3 * 3 * 4);
    volume_is("minkowski() { cube([1, 2, 3]); }", 6);
    // A union distributes: two boxes far apart, each rounded.
    volume_is("minkowski() { union() { cube(1); translate([10, 0, 0]) cube([2, 1, 1]); } sphere(0.5); }",
              rounded_box(1, 1, 1, 0.5) + rounded_box(2, 1, 1, 0.5));
    // A cube and a cylinder: the cylinder tessellated, within the tolerance.
    volume_is("minkowski() { cube([2, 2, 2]); cylinder(h = 1, r = 1); }",
              // prism over the rounded square (side 2, radius 1), height 3
              3 * (4 + 4 * 2 * 1 + pi), 1e-3);
}

TEST_CASE("resize() scales about the origin to the child's exact box, as OpenSCAD", "[resize]") {
    auto bounds = [](const std::string& t) { return lowered(t).bounds(); };
    auto b = bounds("resize([10, 0, 0], auto = true) cube([1, 2, 3]);");
    CHECK(b.hi == glm::dvec3(10, 20, 30));
    b = bounds("resize([0, 10, 0], auto = [true, false, false]) translate([1, 1, 1]) cube([1, 2, 3]);");
    CHECK(b.lo == glm::dvec3(5, 5, 1));
    CHECK(b.hi == glm::dvec3(10, 15, 4));
    b = bounds("resize([4, 6, 8]) rotate([0, 0, 45]) sphere(1);");
    CHECK(b.hi.x - b.lo.x == Approx(4));
    CHECK(b.hi.y - b.lo.y == Approx(6));
    CHECK(b.hi.z - b.lo.z == Approx(8));
    volume_is("resize([4, 6, 8]) sphere(1);", 4.0 / 3 * pi * 2 * 3 * 4);
    b = bounds("resize([2, 0, 0]) cube([1, 2, 3]);");  // 0: that axis kept
    CHECK(b.hi == glm::dvec3(2, 2, 3));
}

namespace {

// The first diagnostic of evaluating and lowering `text` as a file named `path`.
std::string first_message(const std::string& text, const std::string& path = "test.sdl") {
    auto f = std::make_shared<kerf::SourceFile>();
    f->path = path;
    f->text = text;
    try {
        auto r = kerf::evaluate_source(f);
        kerf::lower_to_csg(r.graph);
        return r.warnings.empty() ? std::string("no diagnostic") : kerf::format_diagnostic_head(r.warnings[0]);
    } catch (const kerf::SourceError& e) {
        return kerf::format_diagnostic_head(e.diagnostic());
    }
}

}  // namespace

TEST_CASE("hull(), minkowski() and resize() refuse or warn about bad input, located", "[hull]") {
    CHECK(first_message("hull() {}\ncube(1);") == "test.sdl:1:1: warning: hull: no children: nothing is made");
    CHECK(first_message("cube(1);\n  hull() plane([0, 0, 1], 0);") ==
          "test.sdl:2:10: error: a half-space has no convex hull (it is unbounded): hull() and minkowski() need "
          "bounded solids");
    CHECK(first_message("hull() { cube(1); square(1); }") ==
          "test.sdl:1:19: error: a 2D shape cannot be combined with 3D solids in one operation");
    CHECK(first_message("resize(10) cube(1);") == "test.sdl:1:1: error: resize: newsize must be a list of up to 3 numbers");
    CHECK(first_message("resize(10) cube(1);", "test.scad") ==
          "test.scad:1:1: warning: resize: newsize must be a list of up to 3 numbers (the children are used unchanged)");
    CHECK(first_message("resize([1, -1]) cube(1);") ==
          "test.sdl:1:1: error: resize: newsize must not be negative or infinite, got -1");
    CHECK(first_message("resize([1, 1], auto = 3) cube(1);") ==
          "test.sdl:1:1: error: resize: auto must be true, false or a list of up to 3 of them");
    CHECK(first_message("resize([1, 1]) plane([0, 0, 1], 0);") ==
          "test.sdl:1:1: error: resize: the child is unbounded (a half-space), it has no size");
    CHECK(first_message("minkowski() { difference() { cube(2); cube(1); } sphere(1); }") ==
          "test.sdl:1:1: warning: minkowski: a difference() or intersection() inside is used as its first operand: "
          "the result may be larger than OpenSCAD's");
}

TEST_CASE("hull(), minkowski() and resize() of 2D shapes work on their unit slabs", "[hull][minkowski][resize]") {
    // A top-level 2D model is a plate 1 thick: its volume is the shape's area.
    volume_is("hull() { square(1); translate([3, 0]) square(1); }", 4);
    volume_is("linear_extrude(height = 2) hull() { square(1); translate([3, 1]) square(1); }", 2 * 5);
    // Tapered: the hull of the bottom section and the doubled top one.
    volume_is("linear_extrude(height = 2, scale = 2) hull() { square(1); translate([2, 0]) square(1); }",
              2 * 3 * (1 + 1 + 1.0 / 3));
    // Circles of one radius are exact (a disc round the hull of their
    // centres): a stadium, a rounded rectangle, scaled and turned.
    volume_is("hull() { circle(1); translate([4, 0]) circle(1); }", pi + 8);
    const std::string rounded = "linear_extrude(height = 3) minkowski() { square([2, 3]); circle(0.5); }";
    volume_is(rounded, 3 * (6 + 2 * 0.5 * 5 + pi * 0.25));
    std::size_t points = 0;
    const auto k = kinds(lowered(rounded), &points);
    CHECK(k.at(kerf::csg::PrimKind::Cylinder) == 4);
    CHECK(points <= 8);
    volume_is("scale(2) rotate(30) hull() { circle(0.5); translate([2, 0]) circle(0.5); translate([0, 1.5]) "
              "circle(0.5); }",
              4 * (1.5 + 0.5 * (2 + 1.5 + 2.5) + pi * 0.25));  // (area + r·perimeter + πr²)·2²
    // Unequal circles are tessellated within the tolerance.
    volume_is("hull() { circle(2); translate([5, 0]) circle(1); }",
              [] {  // two tangent segments and the arcs beyond them
                  const double d = 5, s = 1.0 / d, c = std::sqrt(1 - s * s);
                  const double a = std::acos(-s);  // half the big arc's angle beyond the tangents
                  return a * 4 + (pi - a) * 1 + (2 + 1) * c * d;
              }(),
              1e-3);
    const auto b = lowered("linear_extrude(height = 5) resize([4, 0], auto = true) square([1, 2]);").bounds();
    CHECK(b.hi == glm::dvec3(4, 8, 5));
    // Twisted, unevenly scaled, or a tapered sum or resize: tests/lower/test_swept_hull_ops.cpp;
    // revolved: tests/lower/test_revolve_regions.cpp.
}
