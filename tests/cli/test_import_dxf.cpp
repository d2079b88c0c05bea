// import("f.dxf") as a 2D shape (docs/spec.md §10) through the real binary:
// DXF files written here, extruded and measured by `kerf measure`, against
// closed-form areas and, where openscad is installed, against OpenSCAD
// 2021's own import of the same file (its STL export's volume).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "tests/cli/measure_scene.hpp"
#include "tests/cli/run_kerf.hpp"

namespace {

using Pt = std::pair<double, double>;

std::string num(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

std::string entity(const std::string& kind, const std::string& layer,
                   std::initializer_list<std::pair<int, std::string>> codes) {
    std::string s = "0\n" + kind + "\n8\n" + layer + "\n";
    for (const auto& [c, v] : codes) s += std::to_string(c) + "\n" + v + "\n";
    return s;
}
std::string line(Pt a, Pt b, const std::string& layer = "0") {
    return entity("LINE", layer, {{10, num(a.first)}, {20, num(a.second)}, {11, num(b.first)}, {21, num(b.second)}});
}
std::string arc(Pt c, double r, double a1, double a2) {
    return entity("ARC", "0", {{10, num(c.first)}, {20, num(c.second)}, {40, num(r)}, {50, num(a1)}, {51, num(a2)}});
}
std::string circle(Pt c, double r, const std::string& layer = "0") {
    return entity("CIRCLE", layer, {{10, num(c.first)}, {20, num(c.second)}, {40, num(r)}});
}
std::string lwpolyline(std::initializer_list<Pt> pts, const std::string& layer = "0") {
    std::string s = entity("LWPOLYLINE", layer, {{90, std::to_string(pts.size())}, {70, "1"}});
    for (const Pt& p : pts) s += "10\n" + num(p.first) + "\n20\n" + num(p.second) + "\n";
    return s;
}
// A closed LWPOLYLINE of (x, y, bulge) vertices (group 42 where nonzero).
std::string bulged(std::initializer_list<std::array<double, 3>> pts) {
    std::string s = entity("LWPOLYLINE", "0", {{90, std::to_string(pts.size())}, {70, "1"}});
    for (const auto& p : pts) {
        s += "10\n" + num(p[0]) + "\n20\n" + num(p[1]) + "\n";
        if (p[2] != 0) s += "42\n" + num(p[2]) + "\n";
    }
    return s;
}
std::string dxf(const std::string& entities) { return "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n"; }

constexpr double pi = std::numbers::pi;

}  // namespace

TEST_CASE("loose DXF lines join into a closed outline, in any order and direction", "[dxf]") {
    auto dir = test_dir("dxf_lines");
    // A 10 x 6 rectangle, its four sides shuffled and two reversed.
    write_file(dir / "r.dxf", dxf(line({10, 6}, {10, 0}) + line({0, 6}, {0, 0}) + line({10, 0}, {0, 0}) +
                                  line({10, 6}, {0, 6})));
    const std::string scad = "linear_extrude(height = 2) import(\"r.dxf\");";
    check_volume(measure(dir, scad), 120, 1e-6);
    if (const double ref = openscad_volume(dir, scad); std::isfinite(ref)) CHECK(ref == Approx(120).epsilon(1e-6));
}

TEST_CASE("DXF circles stay exact: a plate with a hole and a disc beside it", "[dxf]") {
    auto dir = test_dir("dxf_circles");
    write_file(dir / "p.dxf", dxf(lwpolyline({{0, 0}, {20, 0}, {20, 10}, {0, 10}}) + circle({5, 5}, 2) +
                                  circle({30, 0}, 1.5) + circle({30, 0}, 0.5, "other")));
    // The hole is even-odd inside the plate; the disc outside it is filled.
    const double area = 200 - pi * 4 + pi * 2.25;
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"p.dxf\", layer = \"0\");"), area, 1e-6);
    // Every layer: the small circle on "other" is a hole in the disc.
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"p.dxf\");"), area - pi * 0.25, 1e-6);
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"p.dxf\", layer = \"other\");"), pi * 0.25, 1e-6);
    const double ref = openscad_volume(dir, "linear_extrude(height = 1) import(\"p.dxf\", $fn = 256);");
    if (std::isfinite(ref)) CHECK(ref == Approx(area - pi * 0.25).epsilon(1e-3));
}

TEST_CASE("DXF arcs and lines make a slot, flattened within the curve tolerance", "[dxf]") {
    auto dir = test_dir("dxf_slot");
    // A stadium: two sides of length 8 and two half circles of radius 2.
    write_file(dir / "s.dxf", dxf(line({0, -2}, {8, -2}) + arc({8, 0}, 2, 270, 90) + line({8, 2}, {0, 2}) +
                                  arc({0, 0}, 2, 90, 270)));
    const double area = 8 * 4 + pi * 4;
    check_volume(measure(dir, "linear_extrude(height = 3) import(\"s.dxf\");"), 3 * area, 2e-3);
    const double ref = openscad_volume(dir, "linear_extrude(height = 3) import(\"s.dxf\", $fn = 256);");
    if (std::isfinite(ref)) CHECK(ref == Approx(3 * area).epsilon(2e-3));
}

TEST_CASE("DXF import takes origin and scale as OpenSCAD: (p - origin) * scale", "[dxf]") {
    auto dir = test_dir("dxf_origin");
    write_file(dir / "r.dxf", dxf(lwpolyline({{5, 5}, {8, 5}, {8, 7}, {5, 7}})));
    const std::string scad = "linear_extrude(height = 1) import(\"r.dxf\", origin = [5, 5], scale = 2);";
    const Measured m = measure(dir, scad);
    check_volume(m, 24, 1e-6);
    CHECK(m.out.find("centroid: [3, 2, 0.5]") != std::string::npos);
    CHECK(m.out.find(", [6, 4, 1]]") != std::string::npos);  // the low corner is 0 to rounding
    if (const double ref = openscad_volume(dir, scad); std::isfinite(ref)) CHECK(ref == Approx(24).epsilon(1e-6));
}

TEST_CASE("open DXF paths are closed with a warning, as OpenSCAD, bad files are located errors", "[dxf]") {
    auto dir = test_dir("dxf_bad");
    // The open chain (5,1) (6,1) (6,0) (5,0) is listed from its middle, so
    // joining must extend it both ways before closing it: a unit square.
    write_file(dir / "o.dxf", dxf(lwpolyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}) + line({6, 1}, {6, 0}) +
                                  line({6, 0}, {5, 0}) + line({5, 1}, {6, 1})));
    const std::string scad = "linear_extrude(height = 1) import(\"o.dxf\");";
    const Measured m = measure(dir, scad);
    check_volume(m, 2, 1e-6);
    CHECK(m.err.find("scene.scad:1:28: warning: import: 1 open path(s) in \"o.dxf\" closed") != std::string::npos);
    if (const double ref = openscad_volume(dir, scad); std::isfinite(ref)) CHECK(ref == Approx(2).epsilon(1e-6));

    write_file(dir / "junk.dxf", "hello world\nthis is not dxf\n");
    auto r = run_kerf("check '" + write_file(dir / "j.scad", "linear_extrude(1)\n  import(\"junk.dxf\");\n") + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find("j.scad:2:3: error: import(\"junk.dxf\"): not a readable DXF file") != std::string::npos);

    // A missing file: an error in .sdl, a warning in .scad (as OpenSCAD).
    r = run_kerf("check '" + write_file(dir / "n.sdl", "linear_extrude(1) import(\"missing.dxf\");\n") + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find("n.sdl:1:19: error: cannot find 'missing.dxf'") != std::string::npos);
    r = run_kerf("check '" + write_file(dir / "n.scad", "import(\"missing.dxf\");\n") + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("n.scad:1:1: warning: cannot find 'missing.dxf' (nothing is made)") != std::string::npos);
}

TEST_CASE("OpenSCAD's example013: four INSERTs of two BLOCKs, measured as OpenSCAD exports it", "[dxf]") {
    const std::filesystem::path examples = "/usr/share/openscad/examples/Old";
    if (!std::filesystem::exists(examples / "example013.dxf")) {
        WARN("the openscad examples are not installed: skipped");
        return;
    }
    auto dir = test_dir("dxf_example013");
    std::filesystem::copy_file(examples / "example013.dxf", dir / "example013.dxf");
    // All straight lines, so OpenSCAD's mesh is exact: `openscad -o x.stl
    // example013.scad` has volume 61333.33 (Debian's openscad 2021.01).
    const Measured m = measure(dir, slurp(examples / "example013.scad"));
    check_volume(m, 61333.33, 1e-3);
}

TEST_CASE("LWPOLYLINE bulges are exact arcs: a disc, a rounded square, a bite out of an edge", "[dxf]") {
    auto dir = test_dir("dxf_bulge");
    const double t = std::tan(pi / 8);  // a quarter circle's bulge
    write_file(dir / "disc.dxf", dxf(bulged({{0, 0, 1}, {10, 0, 1}})));
    write_file(dir / "round.dxf", dxf(bulged({{2, 0, 0}, {8, 0, t}, {10, 2, 0}, {10, 8, t}, {8, 10, 0}, {2, 10, t},
                                              {0, 8, 0}, {0, 2, t}})));
    // Clockwise from (3, 0) to (7, 0): the half disc lies inside the square, a hole.
    write_file(dir / "bite.dxf", dxf(bulged({{0, 0, 0}, {3, 0, -1}, {7, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}})));
    check_volume(measure(dir, "linear_extrude(height = 2) import(\"disc.dxf\");"), 2 * 25 * pi, 1e-6);
    const double round = 100 - (4 - pi) * 4;
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"round.dxf\");"), round, 1e-6);
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"bite.dxf\");"), 100 - 2 * pi, 1e-6);
    // Exact: the bulges are discs cut by boxes in the dump, not chords.
    auto r = run_kerf("dump '" + write_file(dir / "d.scad", "import(\"bite.dxf\");\n") + "'", dir);
    CHECK(r.out.find("cylinder z0=0 z1=1 r0=2 r1=2") != std::string::npos);
    // OpenSCAD 2021.01 reads no bulges (the disc file is an empty object
    // there), so its oracle is the same outline drawn with its own circles.
    const double ref = openscad_volume(dir, "$fn = 512; translate([2, 2]) offset(r = 2) square(6); "
                                            "translate([20, 0]) linear_extrude(2) circle(5);");
    if (std::isfinite(ref)) {
        const Measured both = measure(dir, "linear_extrude(height = 1) import(\"round.dxf\"); "
                                           "translate([20, 0]) linear_extrude(2) translate([-5, 0]) import(\"disc.dxf\");");
        check_volume(both, ref, 1e-4);
    }
}

TEST_CASE("bulges that meet other outlines are flattened within the curve tolerance", "[dxf]") {
    auto dir = test_dir("dxf_bulge_flat");
    // A half disc on the square's top edge, and a second square crossing it:
    // the arc meets the other outline, so it is chords, within tolerance.
    write_file(dir / "x.dxf", dxf(bulged({{0, 0, 0}, {4, 0, 0}, {4, 4, 1}, {0, 4, 0}}) +
                                  lwpolyline({{1, 5}, {3, 5}, {3, 7}, {1, 7}})));
    // Even-odd: the half disc (radius 2 about (2, 4)) XOR the square
    // [1, 3] x [5, 7]; their overlap `in` counted on a fine grid.
    const double half = 16 + 2 * pi;
    double in = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = -1 + 2.0 * (i + 0.5) / n, y = 1 + 2.0 * (j + 0.5) / n;
            in += x * x + y * y < 4;
        }
    in *= 4.0 / (double(n) * n);
    const double want = half - in + (4 - in);
    check_volume(measure(dir, "linear_extrude(height = 1) import(\"x.dxf\");"), want, 2e-3);
}

TEST_CASE("a DXF's arcs and circles count in the ignored-facets warning, its lines do not", "[dxf]") {
    auto dir = test_dir("dxf_facets");
    // OpenSCAD cuts a DXF's ARCs and CIRCLEs by $fn, $fa and $fs; kerf keeps
    // them exact (or within the curve tolerance).
    write_file(dir / "c.dxf", dxf(circle({0, 0}, 2)));
    write_file(dir / "a.dxf", dxf(line({0, -2}, {8, -2}) + arc({8, 0}, 2, 270, 90) + line({8, 2}, {0, 2}) +
                                  arc({0, 0}, 2, 90, 270)));
    write_file(dir / "r.dxf", dxf(lwpolyline({{0, 0}, {2, 0}, {2, 1}, {0, 1}})));
    const std::string scene = write_file(dir / "s.scad",
                                         "linear_extrude(1) import(\"r.dxf\", $fn = 8);\n"
                                         "linear_extrude(1) import(\"c.dxf\", $fn = 8);\n"
                                         "linear_extrude(1) import(\"a.dxf\", $fn = 8);\n");
    auto r = run_kerf("check '" + scene + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("s.scad:2:19: warning: $fn, $fa and $fs are ignored on 2 curved shapes (the first here)") !=
          std::string::npos);
    // Without curves nothing is counted.
    const std::string lines = write_file(dir / "l.scad", "linear_extrude(1) import(\"r.dxf\", $fn = 8);\n");
    r = run_kerf("check '" + lines + "'", dir);
    CHECK(r.err.find("ignored on") == std::string::npos);
}
