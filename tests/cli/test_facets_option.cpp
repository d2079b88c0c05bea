// --facets through the real binary (docs/openscad.md, "Facets"): a bad
// value is a usage error, every command that evaluates a scene takes it,
// and `kerf measure --facets openscad` gives the volumes of OpenSCAD 2021's
// own polyhedra. The volumes were computed from OpenSCAD's STL export when
// this test was written — `echo 'SCAD' > one.scad; openscad -o one.stl
// one.scad` (OpenSCAD 2021.01), the signed volume of its triangles — and
// are checked again against a fresh export where openscad is installed.
#include <catch2/catch.hpp>

#include <cmath>

#include "tests/cli/measure_scene.hpp"

TEST_CASE("the facets option takes auto, exact or openscad, anything else is exit 2 with one line") {
    auto dir = test_dir("facets_option");
    const std::string scene = write_file(dir / "nut.scad", "cylinder(h = 3, r = 5, $fn = 6);\n");
    for (const char* cmd : {"render", "check", "dump", "measure"}) {
        const auto r = run_kerf(std::string(cmd) + " '" + scene + "' --facets foo", dir);
        INFO(cmd);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == "kerf: error: --facets expects auto, exact or openscad, got 'foo'");
    }
    for (const char* mode : {"auto", "exact", "openscad"}) {
        INFO(mode);
        CHECK(run_kerf("check '" + scene + "' --facets " + mode, dir).status == 0);
        CHECK(run_kerf("dump '" + scene + "' --facets " + mode, dir).status == 0);
    }
    CHECK(run_kerf("check '" + scene + "' --facets", dir).status == 2);  // a value is needed
}

TEST_CASE("kerf measure --facets openscad measures OpenSCAD 2021's polyhedra", "[facets]") {
    auto dir = test_dir("facets_measure");
    const struct {
        const char* scad;
        double volume;  // OpenSCAD 2021.01's STL export of `openscad`, or of `scad` itself
        const char* openscad = nullptr;
    } cases[] = {
        {"sphere(r = 1, $fn = 6);", 2.624998},
        {"sphere(5);", 490.917470},
        {"sphere(r = 3, $fa = 20, $fs = 0.5);", 107.485650},
        {"cylinder(h = 3, r = 5, $fn = 6);", 194.855850},
        {"cylinder(h = 4, r1 = 0, r2 = 2, $fn = 7);", 14.594204},
        {"linear_extrude(2) circle(3);", 52.900703},
        {"linear_extrude(1) offset(r = 1, $fn = 8) square(2);", 14.828436},
        {"rotate_extrude($fn = 7) translate([2, 0]) square(1);", 13.682019},
        {"rotate_extrude($fn = 16) translate([3, 0]) circle(1);", 56.235463},
        {"rotate_extrude(angle = 100, $fn = 12) translate([2, 0]) circle(1, $fn = 5);", 7.839224},
        {"rotate_extrude(angle = -100, $fn = 12) translate([-2, 0]) circle(1, $fn = 5);", 7.839201},
        {"rotate_extrude($fn = 12) difference() { translate([1, 0]) square([4, 1]); translate([4, 0]) square(2); }",
         44.999979},
        {"hull() { sphere(1); translate([3, 0, 0]) sphere(1.5); }", 16.910344},
        // A twist in OpenSCAD's flat slices (the exact sweep is 250; tests/lower/test_twist_slices.cpp).
        {"linear_extrude(10, twist = 90) square(5);", 264.656337},
        {"linear_extrude(10, twist = 45) difference() { square(6, center = true); square(3, center = true); }", 285.829067},
        // kerf's own solids, as their OpenSCAD equivalents (docs/openscad.md, "Facets").
        {"cone(h = 4, r = 2);", 14.594204, "cylinder(h = 4, r1 = 2, r2 = 0);"},
        {"torus(R = 3, r = 1, $fn = 16);", 56.235463, "rotate_extrude($fn = 16) translate([3, 0]) circle(1);"},
    };
    const bool live = std::system("command -v openscad >/dev/null 2>&1") == 0;
    if (!live) WARN("openscad is not installed: the stored volumes only");
    for (const auto& c : cases) {
        INFO(c.scad);
        const Measured m = measure(dir, c.scad, " --facets openscad");
        CHECK(m.err.empty());  // nothing ignored, nothing warned
        check_volume(m, c.volume, 2e-4);
        if (live) CHECK(openscad_volume(dir, c.openscad ? c.openscad : c.scad) == Approx(c.volume).epsilon(1e-5));
    }
}

TEST_CASE("kerf measure --facets exact: the hex nut is the round cylinder") {
    auto dir = test_dir("facets_exact_measure");
    const Measured m = measure(dir, "cylinder(h = 3, r = 5, $fn = 6);", " --facets exact");
    check_volume(m, M_PI * 25 * 3, 2e-4);  // not the hexagon's 194.86
    CHECK(m.err.find("ignored on 1 curved shape") != std::string::npos);
}
