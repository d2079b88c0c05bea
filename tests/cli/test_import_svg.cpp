// import("f.svg") as a 2D shape (docs/spec.md §10) through the real binary:
// SVG files written here, extruded and measured by `kerf measure`, against
// closed-form areas, the placements OpenSCAD 2021.01 gives (measured with
// `openscad -o x.stl` and written down as numbers), and, where openscad is
// installed, its own import of the same file (its STL export's volume).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <sstream>

#include "tests/cli/measure_scene.hpp"
#include "tests/cli/run_kerf.hpp"

namespace {

constexpr double pi = std::numbers::pi;

std::string svg(const std::string& attrs, const std::string& body) {
    return "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" " + attrs + ">\n" + body + "\n</svg>\n";
}

// The extruded file's volume (= its area) by kerf, checked against `want`.
Measured extrude(const std::filesystem::path& dir, const std::string& file, const std::string& body,
                 const std::string& args = "", const std::string& attrs = "") {
    write_file(dir / file, svg(attrs, body));
    return measure(dir, "linear_extrude(height = 1) import(\"" + file + "\"" + args + ");");
}

// OpenSCAD's volume of the same extrusion (NaN without openscad).
double reference(const std::filesystem::path& dir, const std::string& file, const std::string& args = "") {
    return openscad_volume(dir, "linear_extrude(height = 1) import(\"" + file + "\"" + args + ");");
}

// The x/y bounds `kerf measure` prints: {x0, y0, x1, y1}.
std::array<double, 4> bounds(const Measured& m) {
    std::array<double, 4> b{NAN, NAN, NAN, NAN};
    const std::size_t at = m.out.find("bounds: [[");
    if (at == std::string::npos) return b;
    double z;
    char c;
    std::istringstream in(m.out.substr(at + 10));
    in >> b[0] >> c >> b[1] >> c >> z >> c >> c >> c >> b[2] >> c >> b[3];
    return b;
}

void check_bounds(const Measured& m, std::array<double, 4> want, double tol = 1e-6) {
    const auto b = bounds(m);
    INFO(m.out);
    for (int i = 0; i < 4; ++i) CHECK(std::abs(b[i] - want[i]) <= tol * (1 + std::abs(want[i])));
}

}  // namespace

TEST_CASE("SVG pages map to millimetres as OpenSCAD 2021.01 maps them", "[svg]") {
    auto dir = test_dir("svg_units");
    const std::string rect = "<rect x=\"10\" y=\"20\" width=\"100\" height=\"50\"/>";
    // User units are millimetres; y is flipped about the page's height, a
    // unitless height being 1/dpi inch (dpi 72 unless given), px 1/96 inch.
    struct Case {
        const char* attrs;
        const char* args;
        std::array<double, 4> b;
    } cases[] = {
        {"", "", {10, -70, 110, -20}},  // no height: flipped about y = 0
        {"width=\"200\" height=\"100\"", "", {10, -70 + 100 * 25.4 / 72, 110, -20 + 100 * 25.4 / 72}},
        {"width=\"200\" height=\"100\"", ", dpi = 25.4", {10, 30, 110, 80}},
        {"width=\"200px\" height=\"100px\"", "", {10, -70 + 100 * 25.4 / 96, 110, -20 + 100 * 25.4 / 96}},
        {"width=\"2in\" height=\"1in\"", "", {10, -70 + 25.4, 110, -20 + 25.4}},
        {"width=\"20cm\" height=\"10cm\"", "", {10, 30, 110, 80}},
        {"width=\"200\" height=\"100\"", ", center = true", {-50, -25, 50, 25}},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string file = "u" + std::to_string(i++) + ".svg";
        INFO(file << " " << c.attrs << c.args);
        const Measured m = extrude(dir, file, rect, c.args, c.attrs);
        check_volume(m, 5000, 1e-9);
        check_bounds(m, c.b);
        if (const double ref = reference(dir, file, c.args); std::isfinite(ref)) CHECK(ref == Approx(5000).epsilon(1e-5));
    }
}

TEST_CASE("SVG viewBox and preserveAspectRatio scale and place as in OpenSCAD 2021.01", "[svg]") {
    auto dir = test_dir("svg_viewbox");
    const std::string rect = "<rect x=\"10\" y=\"5\" width=\"10\" height=\"5\"/>";
    struct Case {
        const char* attrs;
        double area;
        std::array<double, 4> b;
    } cases[] = {
        // 200 mm for 20 user units: 10 mm each.
        {"width=\"200mm\" height=\"100mm\" viewBox=\"0 0 20 10\"", 5000, {100, 0, 200, 50}},
        // OpenSCAD 2021.01 adds min-y where SVG subtracts it (x is right):
        // measured y in [-50, 0] for min-y 5 where SVG would place the rect
        // at [50, 100].
        {"width=\"200mm\" height=\"100mm\" viewBox=\"5 5 20 10\"", 5000, {50, -50, 150, 0}},
        {"width=\"100mm\" height=\"100mm\" viewBox=\"0 0 20 10\"", 1250, {50, 25, 100, 50}},  // meet, centred
        {"width=\"100mm\" height=\"100mm\" viewBox=\"0 0 20 10\" preserveAspectRatio=\"xMinYMin\"", 1250, {50, 50, 100, 75}},
        {"width=\"100mm\" height=\"100mm\" viewBox=\"0 0 20 10\" preserveAspectRatio=\"xMaxYMax slice\"", 5000,
         {0, 0, 100, 50}},
        {"width=\"100mm\" height=\"100mm\" viewBox=\"0 0 20 10\" preserveAspectRatio=\"none\"", 2500, {50, 0, 100, 50}},
        // No width or height: the viewBox's size in unitless (1/72 inch) units.
        {"viewBox=\"0 0 200 100\"", 50 * 25.4 * 25.4 / 72 / 72, {10 * 25.4 / 72, 90 * 25.4 / 72, 20 * 25.4 / 72, 95 * 25.4 / 72}},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string file = "v" + std::to_string(i++) + ".svg";
        INFO(file << " " << c.attrs);
        const Measured m = extrude(dir, file, rect, "", c.attrs);
        check_volume(m, c.area, 1e-9);
        check_bounds(m, c.b);
        if (const double ref = reference(dir, file); std::isfinite(ref)) CHECK(ref == Approx(c.area).epsilon(1e-5));
    }
}

TEST_CASE("SVG circles, ellipses and rounded rects are exact", "[svg]") {
    auto dir = test_dir("svg_exact");
    check_volume(extrude(dir, "c.svg", "<circle cx=\"3\" cy=\"4\" r=\"10\"/>"), 100 * pi, 1e-6);
    // An ellipse under a rotation and a skew keeps its area times the skew's determinant 1.
    check_volume(extrude(dir, "e.svg", "<ellipse cx=\"5\" cy=\"5\" rx=\"6\" ry=\"3\" transform=\"rotate(30) skewX(20)\"/>"),
                 18 * pi, 1e-6);
    const Measured r = extrude(dir, "r.svg", "<rect width=\"10\" height=\"10\" rx=\"2\"/>");
    check_volume(r, 100 - (4 - pi) * 4, 1e-6);
    check_bounds(r, {0, -10, 10, 0});
    // ry alone rounds with rx = ry; each radius is clamped to half its side:
    // here the whole rect is the ellipse of radii 5 and 2.
    check_volume(extrude(dir, "r2.svg", "<rect width=\"10\" height=\"4\" ry=\"30\"/>"), 10 * pi, 1e-6);
    if (const double ref = reference(dir, "c.svg", ", $fn = 512"); std::isfinite(ref))
        CHECK(ref == Approx(100 * pi).epsilon(2e-2));  // OpenSCAD flattens circles coarsely
}

TEST_CASE("SVG path data: every command, absolute and relative, curves within the tolerance", "[svg]") {
    auto dir = test_dir("svg_paths");
    // A circle of radius 10 from two arcs, one absolute, one relative.
    check_volume(extrude(dir, "a.svg", "<path d=\"M 0 10 A 10 10 0 0 1 0 -10 a 10 10 0 0 1 0 20 Z\"/>"), 100 * pi, 1e-3);
    // A cubic lobe y = 15t(1-t), x = 30t² - 20t³ over its chord: ∫y dx = 30;
    // S mirrors it below the axis, the even-odd figure eight is 60.
    check_volume(extrude(dir, "c.svg", "<path d=\"M0 0 C 0 5 10 5 10 0 Z\"/>"), 30, 1e-3);
    check_volume(extrude(dir, "s.svg", "<path d=\"M0 0C0,5,10,5,10,0S20-5 20 0Z\"/>"), 60, 1e-3);
    // Quadratic: y = 20t(1-t) over x = 10t, 100/3 each; T mirrors it.
    check_volume(extrude(dir, "q.svg", "<path d=\"M0 0 Q 5 10 10 0 T 20 0 Z\"/>"), 200.0 / 3, 1e-3);
    // The large arc of an ellipse (5, 10, turned 30°) over a chord of 10:
    // rx·ry·(π − (θ − sin θ)/2), θ the chord's angle on the unit circle.
    const double cx = 10 * std::cos(pi / 6) / 5, cy = 10 * std::sin(pi / 6) / 10, th = 2 * std::asin(std::hypot(cx, cy) / 2);
    check_volume(extrude(dir, "e.svg", "<path d=\"M0 0 A 5 10 30 1 0 10 0 Z\"/>"), 50 * (pi - (th - std::sin(th)) / 2),
                 1e-3);
    // H, V, implicit repeats and a relative subpath: even-odd, a hole.
    const Measured h = extrude(dir, "h.svg", "<path d=\"M0,0 h10 v10 H0 z m2,2 l6,0 0,6 -6,0 z\"/>");
    check_volume(h, 64, 1e-9);
    check_bounds(h, {0, -10, 10, 0});
    // Numbers run together, compact arc flags, an implicit repeat: a disc of radius 5.
    check_volume(extrude(dir, "f.svg", "<path d=\"M-5-0a5,5,0,1010,0 5,5 0 00-10,0z\"/>"), 25 * pi, 1e-3);
    if (const double ref = reference(dir, "c.svg"); std::isfinite(ref)) CHECK(ref == Approx(30).epsilon(1e-2));
    if (const double ref = reference(dir, "h.svg"); std::isfinite(ref)) CHECK(ref == Approx(64).epsilon(1e-9));
}

TEST_CASE("SVG shapes are united, a path's subpaths even-odd, as OpenSCAD 2021.01", "[svg]") {
    auto dir = test_dir("svg_fill");
    struct Case {
        const char* body;
        double area;
    } cases[] = {
        {"<rect width=\"10\" height=\"10\"/><rect x=\"5\" y=\"5\" width=\"10\" height=\"10\"/>", 175},
        {"<rect width=\"10\" height=\"10\"/><rect x=\"2\" y=\"2\" width=\"6\" height=\"6\"/>", 100},
        // The fill rule and the fill are ignored, as OpenSCAD 2021.01 does.
        {"<path fill-rule=\"nonzero\" fill=\"none\" d=\"M0 0 H10 V10 H0 Z M2 2 H8 V8 H2 Z\"/>", 64},
        {"<path d=\"M0 0 H10 V10 H0 Z M5 5 H15 V15 H5 Z\"/>", 150},
        {"<polygon points=\"0,0 10,0 10,10\"/>", 50},
        {"<path d=\"M0 0 L10 0 L10 10 L0 0\"/>", 50},  // ends where it starts: closed
        // Closed outlines are not stroked.
        {"<rect width=\"10\" height=\"10\" style=\"fill:none;stroke:black;stroke-width:2\"/>", 100},
        // Transforms, nested: skewX keeps area, matrix scales by its determinant 2.
        {"<g transform=\"translate(10,20)\"><g transform=\"skewX(30)\"><rect width=\"1\" height=\"1\"/></g></g>"
         "<rect width=\"2\" height=\"1\" transform=\"matrix(1 0.5 0 2 -5 -5)\"/>"
         "<a><svg><rect width=\"2\" height=\"2\" transform=\"rotate(45 1 1) scale(1.5)\"/></svg></a>",
         14},
        // Definitions are not drawn.
        {"<defs><rect width=\"10\" height=\"10\"/></defs><rect x=\"20\" width=\"5\" height=\"5\"/>", 25},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string file = "f" + std::to_string(i++) + ".svg";
        INFO(file << " " << c.body);
        check_volume(extrude(dir, file, c.body), c.area, 1e-9);
        if (const double ref = reference(dir, file); std::isfinite(ref)) CHECK(ref == Approx(c.area).epsilon(1e-5));
    }
}

TEST_CASE("open SVG paths are drawn as their stroke, as OpenSCAD 2021.01 draws them", "[svg]") {
    auto dir = test_dir("svg_stroke");
    struct Case {
        const char* body;
        double area;
    } cases[] = {
        // Width 1 unless given (not inherited), square caps, miter joins.
        {"<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\"/>", 11},
        {"<g stroke-width=\"2\"><line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\"/></g>", 11},
        {"<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" stroke-width=\"2\"/>", 24},
        {"<polyline points=\"0,0 10,0 10,10\" stroke-width=\"2\"/>", 44},
        {"<polyline points=\"0,0 10,0\" style=\"stroke-linecap:butt\"/>", 10},
        {"<polyline points=\"0,0 10,0\" stroke-linecap=\"round\"/>", 10 + pi / 4},
        {"<polyline points=\"0,0 10,0 10,10\" stroke-linejoin=\"round\" stroke-width=\"2\"/>", 44 - (1 - pi / 4)},
        // The stroke scales with the transform.
        {"<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" transform=\"scale(2)\"/>", 44},
        // An open subpath stroked beside a closed one filled.
        {"<path d=\"M0 0 L10 0 L10 10 M20 0 H30 V10 H20 Z\"/>", 121},
    };
    int i = 0;
    for (const Case& c : cases) {
        const std::string file = "s" + std::to_string(i++) + ".svg";
        INFO(file << " " << c.body);
        check_volume(extrude(dir, file, c.body), c.area, 2e-4);
        if (const double ref = reference(dir, file); std::isfinite(ref)) CHECK(ref == Approx(c.area).epsilon(1e-4));
    }
}

TEST_CASE("a mixed SVG drawing measures as OpenSCAD 2021.01's import of it", "[svg]") {
    auto dir = test_dir("svg_mixed");
    // A viewBox page, nested transforms, a rounded rect holding a turned
    // trapezoid, a circle, a Bézier outline with an arc-drawn hole, and a
    // stroked polyline. `openscad -o x.stl`: volume 3238.61.
    const std::string body =
        "<g transform=\"translate(30 20)\"><rect x=\"-28\" y=\"-18\" width=\"56\" height=\"36\" rx=\"4\"/>"
        "<g transform=\"rotate(15)\"><path d=\"M -10 -5 h 20 l 5 10 h -30 z\"/></g></g>"
        "<circle cx=\"70\" cy=\"20\" r=\"8\"/>"
        "<path d=\"M 80 5 C 90 -5, 100 15, 110 5 L 110 35 Q 95 45 80 35 Z M 90 15 a 4 4 0 1 0 8 0 a 4 4 0 1 0 -8 0 z\"/>"
        "<polyline points=\"0,45 20,50 40,45\" stroke-width=\"2\"/>";
    const Measured m = extrude(dir, "logo.svg", body, "", "width=\"60mm\" height=\"40mm\" viewBox=\"0 0 60 40\"");
    check_volume(m, 3238.61, 1e-3);
    check_bounds(m, {-1.21, -11.03, 110, 38}, 0.2);  // bounds of the measure's ray grid, 1/256 of the size
    if (const double ref = reference(dir, "logo.svg"); std::isfinite(ref)) CHECK(ref == Approx(3238.61).epsilon(1e-5));
}

TEST_CASE("bad SVG files are located errors, what kerf does not draw, a warning", "[svg]") {
    auto dir = test_dir("svg_bad");
    auto check_scad = [&](const std::string& file, const std::string& text, const std::string& args = "") {
        write_file(dir / file, text);
        return run_kerf("check '" + write_file(dir / "s.scad", "linear_extrude(1)\n  import(\"" + file + "\"" + args + ");\n") + "'",
                        dir);
    };
    // The error's first line without the folder of the scene.
    auto error = [&](const KerfRun& r) {
        const std::string line = first_line(r.err), at = dir.string() + "/";
        return line.rfind(at, 0) == 0 ? line.substr(at.size()) : line;
    };
    auto r = check_scad("x.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<rect width=\"1\" height=\"1\">\n</svg>\n");
    CHECK(r.status == 1);
    CHECK(error(r) == "s.scad:2:3: error: import(\"x.svg\"): not a readable SVG file: line 3: Opening and ending tag "
                      "mismatch: rect line 2 and svg");

    r = check_scad("h.svg", "<html><body/></html>\n");
    CHECK(r.status == 1);
    CHECK(error(r) == "s.scad:2:3: error: import(\"h.svg\"): not an SVG file: the root element is <html>, not <svg>");

    r = check_scad("p.svg", svg("", "<path d=\"M0 0 L10 0 L10 x10 Z\"/>"));
    CHECK(r.status == 1);
    CHECK(error(r) == "s.scad:2:3: error: import(\"p.svg\"): line 3: path data (d) of <path>: expected a number "
                               "at character 16, got 'x'");
    r = check_scad("p2.svg", svg("", "<path d=\"L10 0\"/>"));
    CHECK(first_line(r.err).find("expected a moveto (M or m) at character 1, got 'L'") != std::string::npos);

    r = check_scad("t.svg", svg("", "\n<rect width=\"1\" height=\"1\" transform=\"turn(3)\"/>"));
    CHECK(r.status == 1);
    CHECK(error(r) == "s.scad:2:3: error: import(\"t.svg\"): line 4: transform of <rect>: expected a transform "
                               "(matrix, translate, scale, rotate, skewX, skewY) at character 1, got 't'");

    r = check_scad("w.svg", svg("", "<text>Hi</text>\n<image/><text>again</text>\n<rect width=\"1\" height=\"1\"/>"));
    CHECK(r.status == 0);
    CHECK(r.err.find("s.scad:2:3: warning: import: \"w.svg\" line 4: <image> is not imported") != std::string::npos);
    CHECK(r.err.find("s.scad:2:3: warning: import: \"w.svg\" line 3: <text> (and 1 more) is not imported") !=
          std::string::npos);

    r = check_scad("e.svg", svg("", "<text>Hi</text>"));
    CHECK(r.status == 0);
    CHECK(r.err.find("warning: import: \"e.svg\" holds no shape: the empty shape") != std::string::npos);

    r = check_scad("e.svg", svg("", ""), ", dpi = 0");
    CHECK(r.err.find("s.scad:2:3: warning: import: dpi must be positive, got 0") != std::string::npos);

    // Curves flattened past the list limit stop at it, before the memory is spent.
    write_file(dir / "big.svg", svg("", "<path d=\"M0 0 A 1 1 0 0 1 2 0 A 1 1 0 0 1 0 0 Z\"/>"));
    r = run_kerf("check '" + write_file(dir / "b.scad", "import(\"big.svg\");\n") + "' --max-list 100", dir);
    CHECK(r.status == 1);
    CHECK(error(r) == "b.scad:1:1: error: import(\"big.svg\"): line 3: path data (d) of <path>: more than 100 points "
                      "once its curves are flattened");

    // A missing file: an error in .sdl, a warning in .scad (OpenSCAD 2021
    // prints an ERROR for a missing SVG but goes on without it).
    r = run_kerf("check '" + write_file(dir / "n.sdl", "import(\"missing.svg\");\n") + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find("n.sdl:1:1: error: cannot find 'missing.svg'") != std::string::npos);
    r = run_kerf("check '" + write_file(dir / "n.scad", "import(\"missing.svg\");\n") + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("n.scad:1:1: warning: cannot find 'missing.svg' (nothing is made)") != std::string::npos);
}
