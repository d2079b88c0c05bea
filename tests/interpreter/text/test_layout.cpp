// text(): kerf's glyphs against OpenSCAD's own outlines, the flattening
// bound against the true curves, and the errors.
//
// Each reference/CASE.scad was exported by OpenSCAD 2021.01 to CASE.dxf
// (reference/make_reference.sh). Both outlines are tested for even-odd
// membership on a grid over their common box: they must agree almost
// everywhere (OpenSCAD flattens curves coarsely, so they differ only within
// a band along curves), and their boxes must agree.
// The DXFs were made with 128 chords per curve ($fn): OpenSCAD's default
// of about ten differs from the true outline on 1-2 % of the glyph area.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "tests/interpreter/eval_helpers.hpp"
#include "interpreter/text/font.hpp"
#include "interpreter/text/layout.hpp"

using namespace kerf;

namespace {

const std::filesystem::path kReference = std::filesystem::path(KERF_SOURCE_DIR) / "tests/interpreter/text/reference";

struct Outline {
    std::vector<glm::dvec4> edges;
    glm::dvec2 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::dvec4& e) {
        edges.push_back(e);
        lo = glm::min(lo, glm::min(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
        hi = glm::max(hi, glm::max(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
    }
};

// Even-odd: a ray towards +x crosses an odd number of edges. The edges need
// no order, so OpenSCAD's loose LINE entities and kerf's paths are read alike.
bool inside(const std::vector<glm::dvec4>& edges, glm::dvec2 p) {
    bool in = false;
    for (const glm::dvec4& e : edges) {
        if ((e.y > p.y) == (e.w > p.y)) continue;
        const double x = e.x + (p.y - e.y) * (e.z - e.x) / (e.w - e.y);
        if (x > p.x) in = !in;
    }
    return in;
}

// The LINE entities of an OpenSCAD DXF (codes 10/20 start, 11/21 end).
Outline read_dxf(const std::filesystem::path& path) {
    std::ifstream in(path);
    REQUIRE(in);
    Outline o;
    std::string code, value;
    glm::dvec4 e(0);
    int have = 0;
    while (std::getline(in, code) && std::getline(in, value)) {
        const int c = std::stoi(code);
        if (c == 0) have = 0;
        const int slot = c == 10 ? 0 : c == 20 ? 1 : c == 11 ? 2 : c == 21 ? 3 : -1;
        if (slot < 0) continue;
        e[slot] = std::stod(value);
        if (++have == 4) o.add(e);
    }
    return o;
}

// kerf's glyphs of a case: one even-odd edge set per glyph, united.
struct Glyphs {
    std::vector<csg::Polygon2> polys;
    glm::dvec2 lo{INFINITY}, hi{-INFINITY};
    bool contains(glm::dvec2 p) const {
        return std::any_of(polys.begin(), polys.end(), [&](const csg::Polygon2& g) { return inside(g.edges, p); });
    }
};

Glyphs kerf_glyphs(const std::filesystem::path& scad) {
    EvalOptions opt;
    opt.echo = [](const std::string&) {};
    const EvalResult r = evaluate_file(scad.string(), opt);
    CHECK(r.warnings.empty());
    Glyphs g;
    g.polys = r.graph.polygons;
    for (const csg::Polygon2& p : g.polys) g.lo = glm::min(g.lo, p.lo), g.hi = glm::max(g.hi, p.hi);
    return g;
}

}  // namespace

TEST_CASE("text() outlines agree with OpenSCAD's", "[text]") {
    // The cases and what they check: layout (halign, valign, spacing,
    // direction), fonts by fontconfig name, UTF-8, extreme sizes.
    const char* cases[] = {"plain",         "straight", "halign_center", "halign_right", "spacing",
                           "valign_top",    "valign_center", "valign_bottom", "ttb", "serif_bold",
                           "utf8",          "rtl",      "huge",     "no_family"};
    for (const char* name : cases) {
        INFO("case " << name);
        const Outline ref = read_dxf(kReference / (std::string(name) + ".dxf"));
        const Glyphs got = kerf_glyphs(kReference / (std::string(name) + ".scad"));
        REQUIRE(ref.edges.size() > 3);
        REQUIRE(!got.polys.empty());
        // OpenSCAD's chords cut into curves, it rounds its em to whole
        // pixels of a 100 dpi raster and its coordinates to 0.001
        // (docs/openscad.md, "Text"): a thousandth of the text's extent.
        const glm::dvec2 extent = ref.hi - ref.lo;
        const double slack = 1e-3 * std::max(extent.x, extent.y);
        CHECK(got.lo.x == Approx(ref.lo.x).margin(slack));
        CHECK(got.lo.y == Approx(ref.lo.y).margin(slack));
        CHECK(got.hi.x == Approx(ref.hi.x).margin(slack));
        CHECK(got.hi.y == Approx(ref.hi.y).margin(slack));

        int in_ref = 0, differ = 0;
        const int n = 160;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const glm::dvec2 p = ref.lo + extent * glm::dvec2((i + 0.5) / n, (j + 0.5) / n);
                const bool a = inside(ref.edges, p), b = got.contains(p);
                in_ref += a;
                differ += a != b;
            }
        REQUIRE(in_ref > 300);
        CHECK(static_cast<double>(differ) / in_ref < 5e-3);  // measured: at most 0.27 %
    }
}

TEST_CASE("straight glyphs match OpenSCAD's to its grid of 0.001", "[text]") {
    // "H" has no curve: every vertex is the font's own. OpenSCAD's em is
    // round(217.01) = 217 pixels at size 10 and its points lie on a grid
    // of 0.001; kerf's em is exact, size · 100/72.
    const Outline ref = read_dxf(kReference / "straight.dxf");
    const Glyphs got = kerf_glyphs(kReference / "straight.scad");
    const double em = 217.0 / (10000.0 / 64 * 100 / 72);
    CHECK(got.lo.x * em == Approx(ref.lo.x).margin(1e-3));
    CHECK(got.hi.x * em == Approx(ref.hi.x).margin(1e-3));
    CHECK(got.hi.y * em == Approx(ref.hi.y).margin(1e-3));
    CHECK(got.hi.x != Approx(ref.hi.x).margin(1e-4));  // the em differs, and this test sees it
    CHECK(got.lo.y == Approx(0).margin(1e-12));
}

TEST_CASE("flattened curves stay within the tolerance", "[text]") {
    // Random Béziers, each sampled finely against its chords: the distance
    // from a curve point to the chord of its parameter interval is at most
    // the tolerance, and the bound is not wasteful (half the chords break it
    // for most curves).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-10, 10);
    auto dist_to_segment = [](glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
        const glm::dvec2 ab = b - a;
        const double t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
        return glm::length(p - (a + t * ab));
    };
    auto worst = [&](auto&& curve, int chords) {
        double w = 0;
        for (int k = 0; k < chords; ++k) {
            const glm::dvec2 a = curve(static_cast<double>(k) / chords), b = curve(static_cast<double>(k + 1) / chords);
            for (int s = 1; s < 64; ++s) w = std::max(w, dist_to_segment(curve((k + s / 64.0) / chords), a, b));
        }
        return w;
    };
    int tight = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec2 p0(u(rng), u(rng)), p1(u(rng), u(rng)), p2(u(rng), u(rng)), p3(u(rng), u(rng));
        const double tol = std::pow(10.0, -1 - trial % 4);
        auto quad = [&](double t) { return (1 - t) * (1 - t) * p0 + 2 * (1 - t) * t * p1 + t * t * p2; };
        auto cubic = [&](double t) {
            const double s = 1 - t;
            return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3;
        };
        const int nq = text::quadratic_chords(p0, p1, p2, tol), nc = text::cubic_chords(p0, p1, p2, p3, tol);
        INFO("trial " << trial << " tol " << tol);
        CHECK(worst(quad, nq) <= tol);
        CHECK(worst(cubic, nc) <= tol);
        tight += worst(quad, std::max(1, nq / 2)) > tol;
    }
    CHECK(tight > 150);
}

TEST_CASE("the curve tolerance is a knob: finer costs edges, coarser stays close", "[text]") {
    text::TextParams p;
    p.text = "Sog";
    p.tolerance = 1e-2;
    const text::TextShape coarse = text::layout_text(p);
    p.tolerance = 1e-5;
    const text::TextShape fine = text::layout_text(p);
    REQUIRE(coarse.glyphs.size() == 3);
    REQUIRE(fine.glyphs.size() == 3);
    for (std::size_t g = 0; g < 3; ++g) {
        CHECK(fine.glyphs[g].edges.size() > 3 * coarse.glyphs[g].edges.size());
        // Every coarse vertex lies on the true outline, so within the fine
        // tolerance of the fine outline.
        for (const glm::dvec4& e : coarse.glyphs[g].edges) {
            double best = INFINITY;
            for (const glm::dvec4& f : fine.glyphs[g].edges) {
                const glm::dvec2 a(f.x, f.y), b(f.z, f.w), q(e.x, e.y), ab = b - a;
                const double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
                best = std::min(best, glm::length(q - (a + t * ab)));
            }
            CHECK(best <= 1e-5 * p.size * 1.001);
        }
    }
}

TEST_CASE("text() errors name what is wrong", "[text]") {
    text::TextParams p;
    p.text = "A";
    p.font = "No Such Font Family XYZ";
    CHECK_THROWS_AS(text::layout_text(p), text::FontError);
    p.fallback_font = true;  // the OpenSCAD dialect: substitute and say so
    const text::TextShape s = text::layout_text(p);
    CHECK(s.glyphs.size() == 1);
    REQUIRE(s.warnings.size() == 1);
    CHECK(s.warnings[0].find("No Such Font Family XYZ") != std::string::npos);

    text::TextParams q;
    q.text = "A";
    q.halign = "middle";
    CHECK_THROWS_WITH(text::layout_text(q), Catch::Contains("halign") && Catch::Contains("middle"));
    q.halign = "left";
    q.size = 0;
    CHECK_THROWS_AS(text::layout_text(q), std::invalid_argument);
    q.size = 10;
    q.spacing = NAN;
    CHECK_THROWS_WITH(text::layout_text(q), Catch::Contains("spacing"));
}

TEST_CASE("text is the same shape at every size", "[text]") {
    // Unhinted outlines with a tolerance relative to the size: text at
    // size 0.001 or 10^5 is text at size 10, scaled (OpenSCAD's is not: its
    // grid of 0.001 distorts small text).
    text::TextParams p;
    p.text = "Sg&";
    const text::TextShape ref = text::layout_text(p);
    for (double size : {1e-3, 0.37, 1e5}) {
        p.size = size;
        const text::TextShape s = text::layout_text(p);
        REQUIRE(s.glyphs.size() == ref.glyphs.size());
        const double k = size / 10;
        for (std::size_t g = 0; g < s.glyphs.size(); ++g) {
            REQUIRE(s.glyphs[g].edges.size() == ref.glyphs[g].edges.size());
            for (std::size_t e = 0; e < s.glyphs[g].edges.size(); ++e)
                for (int c = 0; c < 4; ++c)
                    CHECK(s.glyphs[g].edges[e][c] == Approx(ref.glyphs[g].edges[e][c] * k).epsilon(1e-12).margin(1e-15 * size));
        }
    }
}

TEST_CASE("the default font is the packaged Liberation Sans", "[text]") {
    const text::Font f = text::find_font("", false, nullptr);
    CHECK(f.family == "Liberation Sans");
    CHECK(f.file.find("LiberationSans-Regular") != std::string::npos);
    const text::Font b = text::find_font("Liberation Serif:style=Bold", false, nullptr);
    CHECK(b.file.find("LiberationSerif-Bold") != std::string::npos);
    // A pattern with no family: kerf's default family in its own dialect
    // (OpenSCAD's, fontconfig's choice, is the case "no_family" above).
    const text::Font n = text::find_font(":style=Bold", false, nullptr);
    CHECK(n.file.find("LiberationSans-Bold") != std::string::npos);
}

TEST_CASE("a font name fontconfig cannot parse: an error in .sdl, a warning and no text in .scad", "[text]") {
    CHECK_THROWS_AS(text::find_font(":charset=xxx", true, nullptr), text::FontNameError);
    const std::string call = "text(\"Won't display\", font = \":charset=xxx\");\n";
    EvalOptions opt;
    opt.echo = [](const std::string&) {};
    const EvalResult scad = evaluate_source(test::source(call, "charset.scad"), opt);
    REQUIRE(scad.warnings.size() == 1);
    CHECK(scad.warnings[0].message ==
          "text: ':charset=xxx' is not a font name (expected 'Family' or 'Family:style=Style'); nothing drawn");
    CHECK(scad.graph.polygons.empty());
    CHECK_THROWS_WITH(evaluate_source(test::source(call, "charset.sdl"), opt),
                      Catch::Contains("text: ':charset=xxx' is not a font name"));
}
