// dxf_dim() and dxf_cross() (docs/language.md, "2D drawings") through the
// real binary: DIMENSION entities of every type OpenSCAD 2021.01 reads,
// against their closed forms and, where openscad is installed, against
// OpenSCAD's own echo of the same calls.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>
#include <tuple>

#include "tests/cli/run_kerf.hpp"

namespace {

// A DIMENSION on layer "dim" named `name`, of type `type`, with the given
// defining points (index 0–6: groups 1x and 2x).
std::string dimension(const std::string& name, int type, double angle,
                      std::initializer_list<std::tuple<int, double, double>> pts) {
    std::string s = "0\nDIMENSION\n8\ndim\n1\n" + name + "\n70\n" + std::to_string(type) + "\n50\n" +
                    std::to_string(angle) + "\n";
    for (const auto& [i, x, y] : pts)
        s += std::to_string(10 + i) + "\n" + std::to_string(x) + "\n" + std::to_string(20 + i) + "\n" +
             std::to_string(y) + "\n";
    return s;
}

std::string line(const std::string& layer, double x1, double y1, double x2, double y2) {
    return "0\nLINE\n8\n" + layer + "\n10\n" + std::to_string(x1) + "\n20\n" + std::to_string(y1) + "\n11\n" +
           std::to_string(x2) + "\n21\n" + std::to_string(y2) + "\n";
}

const char* kScad =
    "f = \"m.dxf\";\n"
    "echo(linear = dxf_dim(file = f, name = \"lin\"), vertical = dxf_dim(file = f, name = \"vert\"),\n"
    "     aligned = dxf_dim(file = f, name = \"al\"), angle = dxf_dim(file = f, name = \"ang\"),\n"
    "     radius = dxf_dim(file = f, name = \"rad\"), ordinate_y = dxf_dim(file = f, name = \"ordy\"),\n"
    "     ordinate_x = dxf_dim(file = f, name = \"ordx\"), scaled = dxf_dim(file = f, name = \"al\", scale = 2),\n"
    "     layer = dxf_dim(file = f, name = \"lin\", layer = \"dim\"));\n"
    "echo(cross = dxf_cross(file = f, layer = \"c\"), moved = dxf_cross(file = f, layer = \"c\", origin = [1, 1], scale = 2));\n"
    "echo(missing = dxf_dim(file = f, name = \"nothere\"), nocross = dxf_cross(file = f, layer = \"dim\"));\n"
    "cube(1);\n";

const char* kEcho =
    "ECHO: linear = 3, vertical = 4, aligned = 5, angle = 45, radius = 5, ordinate_y = 8, ordinate_x = 7, "
    "scaled = 10, layer = 3\n"
    "ECHO: cross = [2, 2], moved = [2, 2]\n"
    "ECHO: missing = undef, nocross = undef\n";

std::string echoes(const std::string& out) {
    std::string kept, line;
    std::istringstream in(out);
    while (std::getline(in, line))
        if (line.rfind("ECHO:", 0) == 0) kept += line + "\n";
    return kept;
}

}  // namespace

TEST_CASE("dxf_dim and dxf_cross read a drawing's measurements as OpenSCAD does", "[dxf]") {
    auto dir = test_dir("dxf_dim");
    write_file(dir / "m.dxf",
               "0\nSECTION\n2\nENTITIES\n" + dimension("lin", 0, 0, {{3, 0, 0}, {4, 3, 4}}) +
                   dimension("vert", 0, 90, {{3, 0, 0}, {4, 3, 4}}) + dimension("al", 1, 0, {{3, 1, 1}, {4, 4, 5}}) +
                   dimension("ang", 2, 0, {{5, 0, 0}, {0, 1, 0}, {3, 0, 0}, {4, 1, 1}}) +
                   dimension("rad", 4, 0, {{0, 1, 1}, {5, 4, 5}}) + dimension("ordy", 6, 0, {{3, 7, 8}}) +
                   dimension("ordx", 70, 0, {{3, 7, 8}}) + line("c", 0, 0, 4, 4) + line("c", 0, 4, 4, 0) +
                   "0\nENDSEC\n0\nEOF\n");
    const std::string scad = write_file(dir / "m.scad", kScad);
    auto r = run_kerf("check '" + scad + "'", dir);
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    CHECK(echoes(r.out + r.err) == kEcho);
    CHECK(r.err.find("m.scad:8:16: warning: dxf_dim: can't find dimension 'nothere' in 'm.dxf', layer ''") !=
          std::string::npos);
    if (std::system("command -v openscad >/dev/null 2>&1") == 0) {
        const std::string log = (dir / "openscad.log").string();
        std::system(("cd '" + dir.string() + "' && openscad -o m.stl m.scad >'" + log + "' 2>&1").c_str());
        CHECK(echoes(slurp(log)) == kEcho);
    }

    // A bad argument is a located warning in the OpenSCAD dialect, and a
    // drawing that is not DXF a located error.
    write_file(dir / "junk.dxf", "hello\nworld\n");
    r = run_kerf("check '" + write_file(dir / "j.scad", "x = dxf_dim(file = \"junk.dxf\", name = \"a\");\n") + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find("j.scad:1:5: error: dxf_dim(\"junk.dxf\"): not a readable DXF file") != std::string::npos);
}
