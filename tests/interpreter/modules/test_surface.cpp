// surface() (docs/language.md, "Height maps") against OpenSCAD 2021.01's
// own meshes of the same files (surface/: steps.dat and the PNGs of
// make_pngs.py): the signed volume, bounds and vertex count of
// `openscad -o x.stl` on `surface(file = ...)`, quoted below, and its vertex
// heights (luminance × 100/255 of the decoded pixels); the mesh's faces are
// in polyhedron()'s order and closed. Broken files are located errors.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <tuple>

#include "tests/interpreter/eval_helpers.hpp"
#include "tests/interpreter/temp_tree.hpp"

using kerf::test::TempTree;

namespace {

const std::string kDir = std::string(KERF_SOURCE_DIR) + "/tests/interpreter/modules/surface/";

kerf::EvalResult run_in(const std::string& dir, const std::string& text, const std::string& script = "test.sdl") {
    kerf::EvalOptions opt;
    opt.echo = [](const std::string&) {};
    return kerf::evaluate_source(kerf::test::source(text, dir + script), opt);
}

std::string error_in(const std::string& dir, const std::string& text, const std::string& script = "test.sdl") {
    try {
        run_in(dir, text, script);
    } catch (const kerf::SourceError& e) {
        return kerf::format_diagnostic_head(e.diagnostic()).substr(dir.size());
    }
    return "no error";
}

struct Measures {
    double volume = 0;  // signed: negative for polyhedron()'s clockwise-from-outside faces
    glm::dvec3 lo{1e300}, hi{-1e300};
    std::size_t points = 0;
    std::set<std::tuple<double, double, double>> at;
};

Measures measure(const kerf::EvalResult& r) {
    REQUIRE(r.graph.meshes.size() == 1);
    const auto& m = r.graph.meshes[0];
    Measures out;
    for (const auto& f : m.faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i)
            out.volume += glm::dot(m.points.at(f[0]), glm::cross(m.points.at(f[i]), m.points.at(f[i + 1]))) / 6;
    for (const auto& p : m.points) {
        out.lo = glm::min(out.lo, p), out.hi = glm::max(out.hi, p);
        out.at.emplace(p.x, p.y, p.z);
    }
    out.points = out.at.size();
    CHECK(m.solid);
    return out;
}

bool has_point(const Measures& m, double x, double y, double z) {
    for (const auto& [px, py, pz] : m.at)
        if (px == x && py == y && std::abs(pz - z) < 1e-4) return true;
    return false;
}

struct OpenScadMesh {
    const char* call;
    double volume;  // of OpenSCAD's STL (its vertices printed to 6 digits)
    glm::dvec3 lo, hi;
    std::size_t points;
};

}  // namespace

TEST_CASE("surface() builds OpenSCAD's mesh of .dat and PNG height maps", "[surface]") {
    // openscad -o x.stl on each call; volume, bounds and distinct vertices of the STL.
    const OpenScadMesh cases[] = {
        {"surface(file = \"steps.dat\");", 30.125, {0, 0, -3.25}, {3, 2, 6}, 28},
        {"surface(file = \"steps.dat\", center = true);", 30.125, {-1.5, -1, -3.25}, {1.5, 1, 6}, 28},
        {"surface(\"rgba8.png\");", 92.77179, {0, 0, 0}, {2, 1, 100}, 14},
        {"surface(\"rgba8.png\", invert = true);", 109.2286, {0, 0, -100.608}, {2, 1, -6.82784}, 14},
        {"surface(\"rgba8.png\", center = true, convexity = 5);", 92.77179, {-1, -0.5, 0}, {1, 0.5, 100}, 14},
        {"surface(\"grey16.png\");", 60.13724, {0, 0, -1}, {1, 2, 100}, 14},
        {"surface(\"palette4.png\");", 140.9193, {0, 0, 0}, {2, 2, 56.0706}, 21},
    };
    for (const auto& c : cases) {
        INFO(c.call);
        const kerf::EvalResult r = run_in(kDir, c.call);
        CHECK(r.warnings.empty());  // closed and outward: orient() turned nothing
        const Measures m = measure(r);
        CHECK(-m.volume == Approx(c.volume).epsilon(1e-5));  // the STL's 6-digit vertices: 4e-6 at -100.608
        for (int k = 0; k < 3; ++k) {
            CHECK(m.lo[k] == Approx(c.lo[k]).margin(1e-5));
            CHECK(m.hi[k] == Approx(c.hi[k]).margin(1e-5));
        }
        CHECK(m.points == c.points);
    }
}

TEST_CASE("surface() of OpenSCAD's example010.dat is OpenSCAD's mesh", "[surface]") {
    const std::string dir = "/usr/share/openscad/examples/Old/";  // the openscad package (scripts/setup.sh)
    if (!std::ifstream(dir + "example010.dat")) return;
    // openscad -o x.stl: 21785.62, 4321 distinct vertices, x and y in [-22.5, 22.5], z in [-10.9927, 9.96117].
    const kerf::EvalResult r = run_in(dir, "surface(file = \"example010.dat\", center = true, convexity = 5);", "t.scad");
    CHECK(r.warnings.empty());
    const Measures m = measure(r);
    // The STL prints the base -10.992667759... as -10.9927: 45² · 3.2e-5 = 0.065 more volume.
    CHECK(-m.volume == Approx(21785.62 - 45 * 45 * (10.9927 - 10.992667759626542)).epsilon(1e-6));
    CHECK(m.points == 4321);
    CHECK(m.lo.x == -22.5);
    CHECK(m.hi.y == 22.5);
    CHECK(m.lo.z == Approx(-10.9927).margin(1e-4));
    CHECK(m.hi.z == Approx(9.96117).margin(1e-5));
}

TEST_CASE("surface() heights: .dat rows at y = 0, 1, ..., the image's bottom row at y = 0", "[surface]") {
    const Measures dat = measure(run_in(kDir, "surface(\"steps.dat\");"));
    // The first row of numbers at y = 0, a cell's centre the mean of its corners (OpenSCAD's STL).
    CHECK(has_point(dat, 0, 0, 1));
    CHECK(has_point(dat, 3, 0, -1));
    CHECK(has_point(dat, 1, 1, 4));
    CHECK(has_point(dat, 3, 2, 6));
    CHECK(has_point(dat, 0.5, 0.5, 1.875));
    CHECK(has_point(dat, 2.5, 1.5, 2.25));
    CHECK(has_point(dat, 3, 2, -3.25));  // the base: lowest height − 1
    // rgba8.png's top row (red, green, blue; alpha 0, 128, 255) at y = 1: 100/255 · 0.2126 · 255 = 21.26.
    const Measures png = measure(run_in(kDir, "surface(\"rgba8.png\");"));
    CHECK(has_point(png, 0, 1, 21.26));
    CHECK(has_point(png, 1, 1, 71.52));
    CHECK(has_point(png, 2, 1, 7.22));
    CHECK(has_point(png, 0, 0, 7.29255));  // (10, 20, 30), alpha 10
    CHECK(has_point(png, 1, 0, 46.1373));
    CHECK(has_point(png, 0.5, 0.5, 36.5525));
    // 16-bit grey: the high byte, 0x80ff → 128 → 50.1961 (not 129 → 50.5882).
    const Measures grey = measure(run_in(kDir, "surface(\"grey16.png\");"));
    CHECK(has_point(grey, 0, 1, 50.1961));
    CHECK(has_point(grey, 0, 2, 7.05882));
    CHECK(has_point(grey, 1, 0, 25.098));
    // invert: OpenSCAD 2021.01's 100/255 · (1 − luminance), as it computes it.
    const Measures inv = measure(run_in(kDir, "surface(\"rgba8.png\", invert = true);"));
    CHECK(has_point(inv, 0, 1, -20.8678));
    CHECK(has_point(inv, 2, 0, -99.6078));
}

TEST_CASE("surface() reads a file once per loop and takes the OpenSCAD dialect's short rows", "[surface]") {
    const kerf::EvalResult loop = run_in(kDir, "for (i = [0:3]) translate([5 * i, 0, 0]) surface(\"steps.dat\");");
    CHECK(loop.graph.meshes.size() == 1);
    TempTree t;
    const std::string dir = t.root.string() + "/";
    t.write("r.dat", "1 2 3\n4 5\n6 7 8 9\n");
    t.write("n.dat", "1 2 3\n4 x 5\n6 7 8\n");
    // OpenSCAD: a short row's missing heights are 0 (21 for r.dat); a word ends the reading (3 for n.dat).
    const kerf::EvalResult r = run_in(dir, "surface(\"r.dat\");", "test.scad");
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0].message ==
          "surface: \"r.dat\" line 1 has 3 heights, line 3 has 4: the missing heights are 0, as OpenSCAD takes them");
    CHECK(-measure(r).volume == Approx(21));
    const kerf::EvalResult n = run_in(dir, "surface(\"n.dat\");", "test.scad");
    REQUIRE(n.warnings.size() >= 1);
    CHECK(n.warnings[0].message ==
          "surface: \"n.dat\" line 2: 'x' is not a number: the heights end there, as OpenSCAD reads them");
    CHECK(-measure(n).volume == Approx(3));
    // A word first on its line adds no row (openscad: 2.5, the plane z = 1 + x + 2y over the unit square).
    t.write("end.dat", "1 2\n3 4\nend of data\n");
    const kerf::EvalResult e = run_in(dir, "surface(\"end.dat\");", "test.scad");
    CHECK(e.warnings.size() == 1);
    CHECK(-measure(e).volume == Approx(2.5));
}

TEST_CASE("surface() errors and warnings are located", "[surface][errors]") {
    TempTree t;
    const std::string dir = t.root.string() + "/";
    t.write("r.dat", "1 2 3\n4 5\n6 7 8\n");
    t.write("n.dat", "# heights\n1 2\n3 four\n");
    t.write("nan.dat", "1 2\n3 nan\n");
    t.write("row.dat", "1 2 3\n");
    t.write("empty.dat", "# nothing\n\n");
    t.write("bad.png", "\x89PNG\r\n\x1a\nnot really");
    t.write("ok.dat", "1 2\n3 4\n");
    CHECK(error_in(dir, "\n  surface(\"missing.dat\");") == "test.sdl:2:3: error: cannot find 'missing.dat'");
    CHECK(error_in(dir, "surface(\"r.dat\");") ==
          "test.sdl:1:1: error: surface(\"r.dat\"): line 2 has 2 heights, line 1 has 3 (every row needs as many)");
    CHECK(error_in(dir, "surface(\"n.dat\");") == "test.sdl:1:1: error: surface(\"n.dat\"): line 3: 'four' is not a number");
    CHECK(error_in(dir, "surface(\"nan.dat\");") == "test.sdl:1:1: error: surface(\"nan.dat\"): line 2: height 'nan' is not finite");
    CHECK(error_in(dir, "surface(\"nan.dat\");", "test.scad") ==
          "test.scad:1:1: error: surface(\"nan.dat\"): line 2: height 'nan' is not finite");
    CHECK(error_in(dir, "surface(\"row.dat\");") ==
          "test.sdl:1:1: error: surface: \"row.dat\" has 1 row of 3 heights: a height map needs 2 rows of 2 to enclose anything");
    CHECK(error_in(dir, "surface(\"empty.dat\");") ==
          "test.sdl:1:1: error: surface: \"empty.dat\" has 0 rows of 0 heights: a height map needs 2 rows of 2 to enclose anything");
    CHECK(error_in(dir, "surface(\"bad.png\");").rfind("test.sdl:1:1: error: surface(\"bad.png\"): not a readable PNG: ", 0) == 0);
    CHECK(error_in(dir, "surface(3);") ==
          "test.sdl:1:1: error: surface: file must be a string naming a .dat height map or a .png image");
    kerf::EvalOptions small;
    small.limits.list_elements = 8;
    small.echo = [](const std::string&) {};
    try {
        kerf::evaluate_source(kerf::test::source("surface(\"ok.dat\");", dir + "test.sdl"), small);
        FAIL("no error");
    } catch (const kerf::SourceError& e) {
        CHECK(e.diagnostic().message == "surface(\"ok.dat\"): 2 x 2 heights make 9 faces, more than the limit 8 (--max-list)");
    }
    // The OpenSCAD dialect: a one-row file warns and makes nothing, as OpenSCAD's flat mesh encloses nothing.
    const kerf::EvalResult row = run_in(dir, "surface(\"row.dat\");", "test.scad");
    CHECK(row.graph.meshes.empty());
    REQUIRE(row.warnings.size() == 1);
    CHECK(row.warnings[0].message.find("(nothing is made)") != std::string::npos);
    // invert does nothing to a .dat file (OpenSCAD ignores it silently): a warning.
    const kerf::EvalResult inv = run_in(dir, "surface(\"ok.dat\", invert = true);");
    REQUIRE(inv.warnings.size() == 1);
    CHECK(inv.warnings[0].message == "surface: invert applies to PNG images only: ignored for \"ok.dat\"");
}
