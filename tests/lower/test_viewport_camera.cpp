// $vpr, $vpt, $vpd and $vpf at the top level place the default camera as
// OpenSCAD 2021's viewport does (docs/openscad.md, "Viewport"). The oracle
// is the closed form of OpenSCAD's camera: it looks down -z from $vpd above
// $vpt, turned by rotate($vpr) (x, then y, then z), and reproduces the
// pictures `openscad --preview -o x.png` makes to a pixel (measured there).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "render/render.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

const double kDeg = M_PI / 180;

// Rz(c)·Ry(b)·Rx(a) applied to +z (towards the camera) and to +y (up), written out.
glm::dvec3 back_of(double a, double b, double c) {
    a *= kDeg, b *= kDeg, c *= kDeg;
    return {std::cos(a) * std::sin(b) * std::cos(c) + std::sin(a) * std::sin(c),
            std::cos(a) * std::sin(b) * std::sin(c) - std::sin(a) * std::cos(c), std::cos(a) * std::cos(b)};
}
glm::dvec3 up_of(double a, double b, double c) {
    a *= kDeg, b *= kDeg, c *= kDeg;
    return {std::sin(a) * std::sin(b) * std::cos(c) - std::cos(a) * std::sin(c),
            std::sin(a) * std::sin(b) * std::sin(c) + std::cos(a) * std::cos(c), std::sin(a) * std::cos(b)};
}

void same(const glm::dvec3& got, const glm::dvec3& want) {
    for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(want[i]).margin(1e-12));
}

csg::Camera camera_of(const std::string& text, const std::string& path = "test.scad") {
    return lower_to_csg(test::evaluated(text, path).graph).camera;
}

}  // namespace

TEST_CASE("the viewport variables place the camera as OpenSCAD's viewport does") {
    const csg::Camera c = camera_of("$vpr = [30, 40, 20]; $vpt = [2, -3, 4]; $vpd = 110; $vpf = 35;\ncube(1);\n");
    same(c.look_at, {2, -3, 4});
    same(c.position, glm::dvec3(2, -3, 4) + 110.0 * back_of(30, 40, 20));
    same(c.up, up_of(30, 40, 20));
    CHECK(c.fov == 35);
    CHECK_FALSE(c.orthographic);
}

TEST_CASE("viewport variables left unset take OpenSCAD's defaults, none set keeps kerf's framing") {
    // OpenSCAD 2021: [55, 0, 25], [0, 0, 0], 140, 22.5 for those not given.
    csg::Camera c = camera_of("$vpd = 80;\ncube(1);\n");
    same(c.position, 80.0 * back_of(55, 0, 25));
    same(c.up, up_of(55, 0, 25));
    CHECK(c.fov == 22.5);
    c = camera_of("$vpr = [90, 0, 0];\ncube(1);\n");
    same(c.position, 140.0 * back_of(90, 0, 0));
    same(c.up, {0, 0, 1});
    // undef is unset, as in OpenSCAD: kerf's own framing (fov 40) stays.
    CHECK(camera_of("$vpr = undef;\ncube(1);\n").fov == 40);
    CHECK(camera_of("cube(1);\n").fov == 40);
    // A camera() statement wins; a $vpr inside a module is not the viewport.
    CHECK(camera_of("$vpr = [0, 0, 0];\ncamera(position = [5, 5, 5]);\ncube(1);\n", "test.sdl").position ==
          glm::dvec3(5));
    CHECK(camera_of("module m() { $vpr = [0, 0, 0]; cube(1); }\nm();\n").fov == 40);
    // So does a vec2 ($vpt = [1, 2] is [1, 2, 0]), in .sdl too, and the last binding.
    c = camera_of("$vpt = [1, 2]; $vpd = 10; $vpr = [0, 0, 0];\ncube(1);\n", "test.sdl");
    same(c.position, {1, 2, 10});
    c = camera_of("$vpd = 10; $vpd = 20; $vpr = [0, 0, 0];\ncube(1);\n");
    same(c.position, {0, 0, 20});
}

TEST_CASE("a -D value sets the viewport like a top-level binding") {
    EvalOptions o;
    o.defines = {{"$vpr", "[0, 0, 0]"}, {"$vpd", "7"}};
    auto f = std::make_shared<SourceFile>();
    f->path = "test.scad";
    f->text = "cube(1);\n";
    const csg::Camera c = lower_to_csg(evaluate_source(f, o).graph).camera;
    same(c.position, {0, 0, 7});
}

TEST_CASE("viewport values OpenSCAD cannot read, or that give no picture, keep the default with a warning") {
    const EvalResult r = test::evaluated(
        "$vpr = \"a\";\n$vpt = [1, 2, 3, 4];\n$vpd = -5;\n$vpf = 180;\ncube(1);\n", "test.scad");
    REQUIRE(r.warnings.size() == 4);
    CHECK(format_diagnostic_head(r.warnings[0]) ==
          "test.scad:1:1: warning: Unable to convert $vpr=\"a\" to a vec3 or vec2 of numbers");
    CHECK(format_diagnostic_head(r.warnings[1]) ==
          "test.scad:2:1: warning: Unable to convert $vpt=[1, 2, 3, 4] to a vec3 or vec2 of numbers");
    CHECK(format_diagnostic_head(r.warnings[2]) ==
          "test.scad:3:1: warning: $vpd=-5 is not a distance above 0 and at most 1e30: the viewport keeps its default");
    CHECK(format_diagnostic_head(r.warnings[3]) ==
          "test.scad:4:1: warning: $vpf=180 is not a field of view between 0 and 180 degrees: the viewport keeps its "
          "default");
    CHECK(lower_to_csg(r.graph).camera.fov == 40);  // none usable: kerf's framing
    const EvalResult s = test::evaluated("$vpd = \"x\"; $vpf = 30;\ncube(1);\n", "test.scad");
    REQUIRE(s.warnings.size() == 1);
    CHECK(format_diagnostic_head(s.warnings[0]) == "test.scad:1:1: warning: Unable to convert $vpd=\"x\" to a number");
    CHECK(lower_to_csg(s.graph).camera.fov == 30);
}

TEST_CASE("a cube seen through the viewport covers the pixels the closed form says") {
    // Looking down at the unit-half cube's top face (z = 1) from 12 above
    // $vpt, turned 30° about z: pixel centre (u, v) on the image plane meets
    // z = 1 at $vpt + 11·(u·right + v·up), right = (cos 30°, sin 30°), up =
    // (−sin 30°, cos 30°); the face covers |x| ≤ 1, |y| ≤ 1.
    const int W = 80, H = 60;
    const double fov = 30, d = 12;
    const glm::dvec2 target(0.5, -0.3);
    const std::string text = "$vpr = [0, 0, 30]; $vpt = [0.5, -0.3, 0]; $vpd = 12; $vpf = 30;\ncube(2, center = true);\n";
    render::RenderOptions o;
    o.width = W, o.height = H, o.threads = 1, o.aov = render::Aov::Depth;
    const render::Image depth = render::render(lower_to_csg(test::evaluated(text, "test.scad").graph), o);
    const double t = std::tan(fov / 2 * kDeg), s = 0.5, cs = std::sqrt(3.0) / 2;
    const glm::dvec2 right(cs, s), up(-s, cs);
    int hits = 0, checked = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double u = ((x + 0.5) / W * 2 - 1) * t * W / H, v = (1 - (y + 0.5) / H * 2) * t;
            const glm::dvec2 p = target + (d - 1) * (u * right + v * up);
            const double edge = std::max(std::abs(p.x), std::abs(p.y));
            if (std::abs(edge - 1) < 0.02) continue;  // a pixel centre on the silhouette's edge
            ++checked;
            INFO("pixel " << x << ", " << y);
            const float got = depth.at(x, y, 0);
            REQUIRE(std::isfinite(got) == (edge < 1));
            if (edge >= 1) continue;
            ++hits;
            CHECK(got == Approx((d - 1) * std::sqrt(1 + u * u + v * v)).epsilon(1e-5));
        }
    CHECK(hits > 350);  // the face is about 20 pixels square
    CHECK(checked > W * H * 9 / 10);
}
