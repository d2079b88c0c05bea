// 2D shapes and linear_extrude through evaluation, lowering and the tracer.
// An extruded circle is the cylinder (the same leaf kind: equal depth AOV),
// an extruded square the box and an extruded polygon square the box too
// (a prism leaf, another code path: depth equal to rounding). Random 2D
// booleans of polygons with holes and circles under random 2D transforms,
// extruded, are checked ray by ray against the scene's point membership
// (csg::contains, no ray code).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "csg/membership.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/render.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

csg::Scene scene_of(const std::string& text) { return test::lowered(text); }

render::Image depth_of(const std::string& solid) {
    render::RenderOptions o;
    o.width = 64, o.height = 48, o.threads = 1, o.aov = render::Aov::Depth;
    return render::render(scene_of("camera(position = [3.1, -4.3, 3.7], look_at = [0, 0, 0.5]);\n" + solid), o);
}

void same_depth(const render::Image& got, const render::Image& want, double rel) {
    test::same_depth(got, want, rel, 300);
}

// Rays from above at random targets near the origin: a ray disagrees when
// a sample before its hit is inside the scene or the point just after it
// is not (csg::contains, no ray code). Returns the disagreeing count.
int disagreeing_rays(const csg::Scene& s, std::mt19937_64& rng, int n, double spread, int* hits = nullptr) {
    std::uniform_real_distribution<double> u(-1, 1);
    int bad = 0;
    for (bool use_float : {false, true}) {
        render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        for (int r = 0; r < n; ++r) {
            const glm::dvec3 o = glm::dvec3(u(rng), u(rng), u(rng)) * 3.0 * spread + glm::dvec3(0, 0, 4 * spread);
            const glm::dvec3 target(spread * u(rng), spread * u(rng), 0.3 * u(rng));
            const glm::dvec3 d = glm::normalize(target - o);
            render::TraceRay ray{o, d, 0, 20 * spread};
            render::TraceHit hit;
            const bool got = tracer.intersect(ray, hit, scratch);
            if (hits) *hits += got;
            const double tol = (use_float ? 1e-4 : 1e-7) * spread;
            bool ok = true;
            const double end = got ? hit.t - tol : 20 * spread;
            for (int k = 0; k < 200 && ok; ++k) ok = !csg::contains(s, o + (end * k / 200.0) * d);
            if (got) ok = ok && csg::contains(s, o + (hit.t + tol) * d);
            bad += !ok;
        }
    }
    return bad;
}

}  // namespace

TEST_CASE("an extruded circle renders as the cylinder it is") {
    same_depth(depth_of("linear_extrude(height = 2) circle(r = 1.2);"), depth_of("cylinder(h = 2, r = 1.2);"), 1e-12);
    same_depth(depth_of("linear_extrude(height = 2, center = true) circle(d = 2);"),
               depth_of("cylinder(h = 2, r = 1, center = true);"), 1e-12);
}

TEST_CASE("extruded squares and polygons render as the boxes they are") {
    const render::Image cube = depth_of("cube([2, 1, 1.5]);");
    same_depth(depth_of("linear_extrude(1.5) square([2, 1]);"), cube, 1e-12);
    same_depth(depth_of("linear_extrude(1.5) polygon([[0, 0], [1, 0], [2, 0], [2, 1], [0, 1]]);"), cube, 1e-9);
    // A hole by paths, and the same hole by difference().
    same_depth(depth_of("linear_extrude(1) polygon([[0,0],[2,0],[2,2],[0,2],[0.5,0.5],[1.5,0.5],[1.5,1.5],[0.5,1.5]],"
                        " paths = [[0,1,2,3],[4,5,6,7]]);"),
               depth_of("difference() { cube([2, 2, 1]); translate([0.5, 0.5, -1]) cube([1, 1, 3]); }"), 1e-9);
}

TEST_CASE("a top-level 2D model is a plate 1 thick on z = 0") {
    const csg::Scene s = scene_of("square(2, center = true);");
    CHECK(s.bounds().lo.z == -0.5);
    CHECK(s.bounds().hi.z == 0.5);
    CHECK(csg::contains(s, {0.9, 0.9, 0.49}));
    CHECK_FALSE(csg::contains(s, {0.9, 0.9, 0.51}));
}

TEST_CASE("random extruded 2D booleans agree with point membership along rays") {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> u(-1, 1);
    auto num = [&](double s) { std::ostringstream o; o.precision(17); o << s * u(rng); return o.str(); };
    auto shape = [&](int k) {
        std::string tf = "translate([" + num(0.8) + ", " + num(0.8) + "]) rotate(" + num(180) + ") scale([" +
                         std::to_string(0.6 + 0.5 * std::abs(u(rng))) + ", " + std::to_string(0.6 + 0.5 * std::abs(u(rng))) + "]) ";
        if (k % 3 == 0) return tf + "circle(r = " + std::to_string(0.3 + 0.4 * std::abs(u(rng))) + ");";
        if (k % 3 == 1) return tf + "square(" + std::to_string(0.4 + 0.6 * std::abs(u(rng))) + ", center = true);";
        std::string pts;
        for (int i = 0; i < 9; ++i) {
            const double a = 2 * M_PI * i / 9, r = 0.3 + 0.7 * std::abs(u(rng));
            pts += (i ? ", [" : "[") + std::to_string(r * std::cos(a)) + ", " + std::to_string(r * std::sin(a)) + "]";
        }
        pts += ", [0.1, 0], [0, 0.15], [-0.1, 0]";  // a hole
        return tf + "polygon([" + pts + "], paths = [[0,1,2,3,4,5,6,7,8], [9,10,11]]);";
    };
    const char* ops[3] = {"union", "intersection", "difference"};
    int rays = 0, bad = 0;
    for (int scene = 0; scene < 12; ++scene) {
        const char* scales[4] = {"1", "0.6", "1.5", "0.25"};
        std::string text = "linear_extrude(height = " + std::to_string(0.5 + std::abs(u(rng))) +
                           ", center = true, scale = " + scales[scene % 4] + ") " + ops[scene % 3] + "() {\n";
        for (int k = 0; k < 4; ++k) text += shape(scene + k) + "\n";
        text += "}\n";
        INFO(text);
        const csg::Scene s = scene_of(text);
        bad += disagreeing_rays(s, rng, 400, 1);
        rays += 800;
    }
    INFO(bad << " of " << rays << " rays disagree");
    // A ray grazing an edge within tol can disagree; they are rare.
    CHECK(bad <= rays / 100);
}

TEST_CASE("extruded text agrees with point membership along rays") {
    // Glyphs with holes, curves and a descender, engraved into a plate and
    // raised, at size 10 (0.001 tolerance: hundreds of edges per glyph).
    std::mt19937_64 rng(15);
    const csg::Scene s = scene_of(
        "difference() { translate([-12, -8, -1]) cube([24, 16, 1.5]);\n"
        "  linear_extrude(height = 3, center = true) text(\"B&g\", halign = \"center\", valign = \"center\"); }\n"
        "translate([0, 0, 1]) linear_extrude(height = 1) text(\"Ø8\", size = 4, halign = \"center\");\n");
    int hits = 0;
    const int bad = disagreeing_rays(s, rng, 1500, 10, &hits);
    INFO(bad << " of 3000 rays disagree, " << hits << " hit");
    CHECK(hits > 1000);
    CHECK(bad <= 30);
}

TEST_CASE("2D rules as OpenSCAD 2021.01 applies them") {
    // openscad -o c.svg of this polygon gives the two outer strips only:
    // the paths' overlap 2 < x < 4 is a hole (even-odd).
    const csg::Scene overlap = scene_of(
        "linear_extrude(1) polygon([[0,0],[4,0],[4,4],[0,4],[2,0],[6,0],[6,4],[2,4]], paths=[[0,1,2,3],[4,5,6,7]]);");
    CHECK(csg::contains(overlap, {1, 2, 0.5}));
    CHECK_FALSE(csg::contains(overlap, {3, 2, 0.5}));
    CHECK(csg::contains(overlap, {5, 2, 0.5}));
    // translate([0, 0, 5]) square(2) exports as the square at the origin: z is ignored.
    const csg::Scene lifted = scene_of("linear_extrude(1) translate([1, 0, 5]) square(2);");
    CHECK(lifted.bounds().lo.z == 0);
    CHECK(lifted.bounds().hi.z == 1);
    CHECK(lifted.bounds().lo.x == 1);
}

TEST_CASE("linear_extrude with a uniform scale: a circle becomes the frustum, a translated square a slanted taper") {
    same_depth(depth_of("linear_extrude(height = 2, scale = 0.4) circle(r = 1.2);"),
               depth_of("cylinder(h = 2, r1 = 1.2, r2 = 0.48);"), 1e-12);
    // OpenSCAD scales each section about the origin: translate([2, 0]) square(1)
    // is [2, 3] x [0, 1] at the bottom and [1, 1.5] x [0, 0.5] at the top (scale 0.5).
    const csg::Scene s = scene_of("linear_extrude(height = 4, scale = [0.5, 0.5]) translate([2, 0]) square(1);");
    CHECK(csg::contains(s, {2.9, 0.9, 0.01}));
    CHECK(csg::contains(s, {1.45, 0.45, 3.99}));
    CHECK_FALSE(csg::contains(s, {1.55, 0.25, 3.99}));
    CHECK_FALSE(csg::contains(s, {2.9, 0.9, 3.0}));  // at z = 3 the section is [1.25, 1.875] x [0, 0.625]
    CHECK(csg::contains(s, {1.8, 0.6, 3.0}));
    CHECK_FALSE(csg::contains(s, {1.9, 0.3, 3.0}));
    CHECK(s.bounds().hi.x == Approx(3));
    CHECK(s.bounds().lo.x == Approx(1));
}
