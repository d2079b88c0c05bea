// multmatrix, scale and color() as OpenSCAD 2021.01 takes them in the .scad
// dialect (docs/openscad.md, "Built-in modules"). The boxes are OpenSCAD's
// own: the vertices of `openscad -o x.stl` of `multmatrix(M) cube(10);`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "tests/interpreter/eval_helpers.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

struct Box {
    glm::dvec3 lo, hi;
};

EvalResult scad(const std::string& text) {
    EvalOptions opt;
    opt.echo = [](const std::string&) {};
    return evaluate_source(source(text, "test.scad"), opt);
}

// The world box of a box primitive's corners (p[0..2] its min, p[3..5] its max).
Box world_box(const Leaf& l) {
    Box b{glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c(l.p[(i & 1) ? 3 : 0], l.p[(i & 2) ? 4 : 1], l.p[(i & 4) ? 5 : 2]);
        const glm::dvec3 w(l.world * glm::dvec4(c, 1));
        b.lo = glm::min(b.lo, w), b.hi = glm::max(b.hi, w);
    }
    return b;
}

std::vector<std::string> warnings_of(const EvalResult& r) {
    std::vector<std::string> out;
    for (const Diagnostic& d : r.warnings) out.push_back(format_diagnostic_head(d));
    return out;
}

}  // namespace

TEST_CASE("a .scad multmatrix is divided by its corner and drops the rest of the last row, as OpenSCAD", "[openscad]") {
    const struct {
        const char* m;
        Box openscad;  // its STL's vertex box
        const char* warning;
    } cases[] = {
        {"[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,2]]", {{0, 0, 0}, {5, 5, 5}}, nullptr},
        {"[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-0.5]]", {{-20, -20, -20}, {0, 0, 0}}, nullptr},
        {"[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0.1,0,0,1]]", {{0, 0, 0}, {10, 10, 10}},
         "test.scad:1:1: warning: multmatrix: the last row's [0.1, 0, 0] is ignored, as OpenSCAD does (the matrix is "
         "used as an affine map)"},
        {"[[1,0,0,1],[0,2,0,0],[0,0,1,0],[0.3,0,0.2,-2]]", {{-5.5, -10, -5}, {-0.5, 0, 0}},
         "test.scad:1:1: warning: multmatrix: the last row's [0.3, 0, 0.2] is ignored, as OpenSCAD does (the matrix "
         "is used as an affine map)"},
        // Short rows and entries that are not numbers keep the identity's.
        {"[[2,0,0],[0,\"a\",0,5]]", {{0, 5, 0}, {20, 15, 10}},
         "test.scad:1:1: warning: multmatrix: m is not a 4x4 or 3x4 matrix of numbers: the entries missing take the "
         "identity's, as OpenSCAD does"},
    };
    for (const auto& c : cases) {
        INFO(c.m);
        const EvalResult r = scad(std::string("multmatrix(") + c.m + ") cube(10);");
        const auto l = leaves(r.graph);
        REQUIRE(l.size() == 1);
        const Box b = world_box(l[0]);
        for (int i = 0; i < 3; ++i) {
            CHECK(b.lo[i] == Approx(c.openscad.lo[i]).margin(1e-12));
            CHECK(b.hi[i] == Approx(c.openscad.hi[i]).margin(1e-12));
        }
        CHECK(warnings_of(r) == (c.warning ? std::vector<std::string>{c.warning} : std::vector<std::string>{}));
    }
    // .sdl keeps its error.
    CHECK(error_of("multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,2]]) cube(10);") ==
          "test.sdl:1:1: error: multmatrix: the last row must be [0, 0, 0, 1] (only affine transforms are supported)");
}

TEST_CASE("a .scad matrix that is not finite removes its children, with OpenSCAD's warning", "[openscad]") {
    for (const char* m : {"[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,0]]", "[[1/0,0,0,0],[0,1,0,0],[0,0,1,0]]"}) {
        INFO(m);
        // The children still run (their echo prints), as in OpenSCAD.
        std::vector<std::string> lines;
        EvalOptions opt;
        opt.echo = [&](const std::string& line) { lines.push_back(line); };
        const EvalResult r = evaluate_source(
            source(std::string("cube(1);\nmultmatrix(") + m + ") { echo(\"child\"); cube(10); }", "test.scad"), opt);
        CHECK(leaves(r.graph).size() == 1);
        CHECK(lines == std::vector<std::string>{"ECHO: \"child\""});
        CHECK(warnings_of(r) == std::vector<std::string>{"test.scad:2:1: warning: multmatrix: Transformation matrix "
                                                         "contains Not-a-Number and/or Infinity - removing object."});
    }
}

TEST_CASE("a .scad transform that flattens its children makes nothing, with a warning", "[openscad]") {
    // OpenSCAD removes a 2D shape scaled to a line (its warning) and keeps a
    // solid flattened to a sheet of no volume, which kerf cannot show.
    EvalResult r = scad("cube(1);\nscale([1, 0]) square(5);");
    CHECK(leaves(r.graph).size() == 1);
    CHECK(warnings_of(r) == std::vector<std::string>{"test.scad:2:1: warning: scale: Scaling a 2D object with 0 - removing object"});
    r = scad("cube(1);\nmultmatrix([[0,0,0,0],[0,1,0,0],[0,0,1,0]]) cube(10);");
    CHECK(leaves(r.graph).size() == 1);
    CHECK(warnings_of(r) ==
          std::vector<std::string>{"test.scad:2:1: warning: multmatrix: the transform flattens its children to no "
                                   "volume: nothing is made (OpenSCAD keeps a flat sheet)"});
    r = scad("scale([1, 1, 0]) cube(5);");
    CHECK(leaves(r.graph).empty());
    CHECK(r.warnings.size() == 1);
    // A 2D shape's z factor is not its business: OpenSCAD scales it in the plane.
    r = scad("scale([2, 1, 0]) square(5);");
    REQUIRE(leaves(r.graph).size() == 1);
    CHECK(r.warnings.empty());
    CHECK(error_of("scale([2, 1, 0]) cube(5);") == "test.sdl:1:1: error: scale: factor must not be 0");
}

TEST_CASE("color(alpha = a) with no colour keeps the colour at opacity a, as OpenSCAD", "[openscad]") {
    auto one = [](const std::string& text) {
        const EvalResult r = scad(text);
        CHECK(r.warnings.empty());
        const auto l = leaves(r.graph);
        REQUIRE(l.size() == 1);
        return l[0];
    };
    // The default light grey at transparency 1 - alpha.
    Leaf l = one("color(alpha = 0.5) cube(1);");
    CHECK(l.material.color == csg::Material{}.color);
    CHECK(l.material.interior == csg::Material{}.color);
    CHECK(l.material.transparency == 0.5);
    // An enclosing material's colour and other parameters stay; undef is no colour.
    l = one("material(color = \"red\", specular = 0.6) color(alpha = 0.25) cube(1);");
    CHECK(l.material.color == glm::dvec3(1, 0, 0));
    CHECK(l.material.specular == 0.6);
    CHECK(l.material.transparency == 0.75);
    CHECK(one("color(undef, 0.4) cube(1);").material.transparency == Approx(0.6));
    CHECK(one("color(undef) cube(1);").material.transparency == 0);
    CHECK(error_of("color(alpha = 0.5) cube(1);") == "test.sdl:1:1: error: color: c is required");
}
