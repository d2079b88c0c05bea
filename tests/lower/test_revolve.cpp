// rotate_extrude through evaluation, lowering and the tracer. A revolved
// circle is the torus (the same leaf kind: equal depth AOV to rounding); a
// revolved square the tube, checked by point membership against the closed
// form ρ in [2, 3], z in [0, 2] with the wedge of a partial angle (OpenSCAD
// 2021.01's: from +x counter-clockwise, clockwise for a negative angle, from
// −x for a profile at x <= 0, exported STL bounds checked with openscad);
// random revolved 2D booleans ray by ray against the scene's membership.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "csg/membership.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/render.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

render::Image depth_of(const std::string& solid) {
    render::RenderOptions o;
    o.width = 64, o.height = 48, o.threads = 1, o.aov = render::Aov::Depth;
    return render::render(test::lowered("camera(position = [7, -9, 6], look_at = [0, 0, 0]);\n" + solid), o);
}

EvalResult eval_scad(const std::string& text) { return test::evaluated(text, "test.scad"); }

// ρ in [2, 3], z in [0, 2], angle from `from` over `sweep` degrees (signed).
bool in_tube(const glm::dvec3& p, double from, double sweep) {
    const double rho = std::hypot(p.x, p.y);
    if (!(rho > 2 && rho < 3 && p.z > 0 && p.z < 2)) return false;
    if (std::abs(sweep) >= 360) return true;
    double a = std::atan2(p.y, p.x) * 180 / M_PI - from;
    if (sweep < 0) a = -a;
    a = std::fmod(a + 720, 360);
    return a < std::abs(sweep);
}

}  // namespace

TEST_CASE("a revolved circle renders as the torus it is", "[revolve]") {
    test::same_depth(depth_of("rotate_extrude() translate([3, 0]) circle(r = 1);"),
                     depth_of("torus(R = 3, r = 1);"), 1e-12);
    // An ellipse with axes along x and y: the torus scaled in z.
    test::same_depth(depth_of("rotate_extrude() translate([3, 0]) scale([1, 2]) circle(r = 1);"),
                     depth_of("scale([1, 1, 2]) torus(R = 3, r = 1);"), 1e-9);
}

TEST_CASE("a revolved square is the tube, partial angles its wedge", "[revolve]") {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-3.5, 3.5);
    struct Case { const char* text; double from, sweep; };
    const Case cases[] = {
        {"rotate_extrude() translate([2, 0]) square([1, 2]);", 0, 360},
        {"rotate_extrude(angle = 90) translate([2, 0]) square([1, 2]);", 0, 90},
        {"rotate_extrude(angle = 250) translate([2, 0]) square([1, 2]);", 0, 250},
        {"rotate_extrude(angle = -90) translate([2, 0]) square([1, 2]);", 0, -90},
        {"rotate_extrude(angle = 400) translate([2, 0]) square([1, 2]);", 0, 360},
        {"rotate_extrude(angle = 90) translate([-3, 0]) square([1, 2]);", 180, 90},
        {"rotate_extrude(angle = 180) polygon([[2, 0], [3, 0], [3, 2], [2, 2]]);", 0, 180},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const csg::Scene s = test::lowered(c.text);
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 p(u(rng), u(rng), u(rng) / 1.5 + 1);
            CHECK(csg::contains(s, p) == in_tube(p, c.from, c.sweep));
        }
    }
    // openscad -o of the 90° and −90° cases: x, y in [0, 3] and y in [−3, 0].
    const csg::Scene quarter = test::lowered(cases[1].text);
    CHECK(quarter.bounds().lo.x == 0);
    CHECK(quarter.bounds().lo.y == 0);
    CHECK(quarter.bounds().hi.x == Approx(3));
    CHECK(test::lowered("rotate_extrude(angle = 0) translate([2, 0]) square(1);").root == csg::kNone);
}

TEST_CASE("random revolved 2D booleans agree with point membership along rays", "[revolve]") {
    std::mt19937_64 rng(2027);
    std::uniform_real_distribution<double> u(-1, 1);
    const std::string text =
        "rotate_extrude(angle = 300) difference() {\n"
        "  translate([2, 0]) rotate(20) square([1.5, 1], center = true);\n"
        "  translate([2.2, 0.1]) circle(r = 0.3);\n"
        "  polygon([[1.5, 0.5], [2.5, 0.2], [2.9, 0.9], [2, 0.7]]);\n"
        "}\n";
    const csg::Scene s = test::lowered(text);
    int rays = 0, bad = 0;
    for (bool use_float : {false, true}) {
        render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        for (int r = 0; r < 400; ++r) {
            const glm::dvec3 o = glm::dvec3(u(rng), u(rng), u(rng)) * 5.0 + glm::dvec3(0, 0, 3);
            const glm::dvec3 target(2.5 * u(rng), 2.5 * u(rng), 0.6 * u(rng));
            const glm::dvec3 d = glm::normalize(target - o);
            render::TraceRay ray{o, d, 0, 30};
            render::TraceHit hit;
            const bool got = tracer.intersect(ray, hit, scratch);
            const double tol = use_float ? 1e-4 : 1e-7;
            bool ok = true;
            const double end = got ? hit.t - tol : 30;
            for (int k = 0; k < 300 && ok; ++k) ok = !csg::contains(s, o + (end * k / 300.0) * d);
            if (got) ok = ok && csg::contains(s, o + (hit.t + tol) * d);
            ++rays;
            bad += !ok;
        }
    }
    INFO(bad << " of " << rays << " rays disagree");
    CHECK(bad <= rays / 100);
}

TEST_CASE("a tilted ellipse or a circle touching the axis is revolved as a polygon within the curve tolerance",
          "[revolve]") {
    // Not a transformed torus: a Lathe leaf over a polygon whose chords stay
    // within 1e-4 (relative) of the curve; membership checked against the
    // ellipse away from that band.
    const csg::Scene tilted = test::lowered("rotate_extrude() translate([3, 0]) rotate(30) scale([1, 2]) circle(1);");
    REQUIRE(tilted.leaves.size() == 1);
    CHECK(tilted.leaves[0].kind == csg::PrimKind::Lathe);
    const csg::Scene horn = test::lowered("rotate_extrude() translate([1, 0]) circle(1);");
    REQUIRE(horn.leaves.size() == 1);
    CHECK(horn.leaves[0].kind == csg::PrimKind::Lathe);
    CHECK(horn.bounds().hi.x == Approx(2));
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-4, 4);
    const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6);
    int checked = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng) / 1.5);
        const double rho = std::hypot(p.x, p.y);
        // The tilted ellipse: rotate back by 30°, then unscale y by 2.
        const double ex = c30 * (rho - 3) + s30 * p.z, ey = (-s30 * (rho - 3) + c30 * p.z) / 2;
        const double f = std::hypot(ex, ey) - 1;
        if (std::abs(f) > 1e-3) {
            CHECK(csg::contains(tilted, p) == (f < 0));
            ++checked;
        }
        const double g = std::hypot(rho - 1, p.z) - 1;
        if (std::abs(g) > 1e-3) CHECK(csg::contains(horn, p) == (g < 0));
    }
    CHECK(checked > 3000);
}

TEST_CASE("rotate_extrude's bad input and OpenSCAD's rules", "[revolve]") {
    // OpenSCAD: "all points for rotate_extrude() must have the same X coordinate sign (range is -1.00 -> 2.00)".
    REQUIRE_THROWS_WITH(test::lowered("rotate_extrude() translate([-1, 0]) square([3, 2]);"),
                        Catch::Equals("test.sdl:1:1: error: rotate_extrude: all points for rotate_extrude() must have "
                                      "the same X coordinate sign (range is -1.00 -> 2.00)"));
    REQUIRE_THROWS_WITH(test::lowered("rotate_extrude() cube(1);"), Catch::Contains("not 3D solids"));
    REQUIRE_THROWS_WITH(test::lowered("rotate_extrude(90) square(1);"), Catch::Contains("deprecated file"));
    // .scad: a 3D child is ignored with a warning, as OpenSCAD does.
    const EvalResult r = eval_scad("rotate_extrude() { translate([2, 0]) square(1); cube(1); }");
    CHECK(r.warnings.size() == 1);
    const csg::Scene s = lower_to_csg(r.graph);
    CHECK(s.leaves.size() == 1);
    CHECK(s.leaves[0].kind == csg::PrimKind::Lathe);
    CHECK(s.bounds().hi.z == 1);
    // .scad: the sign error makes nothing of this rotate_extrude and the run
    // goes on, as OpenSCAD 2021.01 does (it prints an ERROR, exports the
    // cube and exits 0: `openscad -o x.stl` of these two lines); the
    // deprecated positional file argument a warning, the children revolved.
    const EvalResult sign = eval_scad("rotate_extrude() translate([-1, 0]) square([3, 2]);\ncube(1);");
    REQUIRE(sign.warnings.size() == 1);
    CHECK(format_diagnostic_head(sign.warnings[0]) ==
          "test.scad:1:1: warning: rotate_extrude: all points for rotate_extrude() must have the same X coordinate "
          "sign (range is -1.00 -> 2.00) (nothing is made)");
    const csg::Scene cube = lower_to_csg(sign.graph);
    REQUIRE(cube.leaves.size() == 1);
    CHECK(cube.leaves[0].kind == csg::PrimKind::Box);
    const EvalResult dxf = eval_scad("rotate_extrude(90) translate([2, 0]) square(1);");
    CHECK(dxf.warnings.size() == 1);
    CHECK(lower_to_csg(dxf.graph).leaves[0].kind == csg::PrimKind::Lathe);
}
