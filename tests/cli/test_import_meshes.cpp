// import() of OFF, AMF and 3MF end to end (docs/language.md, "Meshes from
// files"): `kerf measure` of the imported solid against its closed form and
// against OpenSCAD 2021.01's own volume of the same import (where openscad
// is installed): a model OpenSCAD exported in each format, and OFF prisms
// with concave and non-planar faces written here.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

#include "interpreter/interpreter.hpp"
#include "tests/cli/measure_scene.hpp"

namespace {

// A 20 × 30 × 40 block with a hexagonal hole of circumradius 5 through it,
// and a separate 10 mm cube: 24000 − 40 · (3√3/2) · 25 + 1000.
const char* kModel =
    "difference() { cube([20, 30, 40]); translate([10, 15, -1]) cylinder(r = 5, h = 42, $fn = 6); }\n"
    "translate([30, 0, 0]) cube(10);";
const double kModelVolume = 25000 - 40 * 1.5 * std::sqrt(3.0) * 25;

// The exact volume of what an import made: the parts' meshes (disjoint
// here), each face fanned (OpenSCAD's exports are triangles), clockwise
// from outside as the scene graph keeps them.
double mesh_volume(const std::string& scene) {
    kerf::EvalOptions opt;
    opt.echo = [](const std::string&) {};
    const kerf::EvalResult r = kerf::evaluate_file(scene, opt);
    double v = 0;
    for (const auto& m : r.graph.meshes)
        for (const auto& f : m.faces)
            for (std::size_t i = 1; i + 1 < f.size(); ++i)
                v -= glm::dot(m.points[f[0]], glm::cross(m.points[f[i]], m.points[f[i + 1]])) / 6;
    return v;
}

bool have_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

// An L-shaped section (area 4) extruded by 1, as OFF polygons: the caps are
// concave hexagons; `lift` raises the top's corner (3, 1) off its plane.
std::string l_prism(double lift) {
    const double xy[6][2] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}};
    std::string s = "OFF\n12 8 0\n";
    for (int z = 0; z < 2; ++z)
        for (int i = 0; i < 6; ++i)
            s += std::to_string(xy[i][0]) + " " + std::to_string(xy[i][1]) + " " +
                 std::to_string(z + (z == 1 && i == 2 ? lift : 0)) + "\n";
    s += "6 5 4 3 2 1 0\n6 6 7 8 9 10 11\n";
    for (int i = 0; i < 6; ++i) {
        const int j = (i + 1) % 6;
        s += "4 " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(6 + j) + " " +
             std::to_string(6 + i) + "\n";
    }
    return s;
}

}  // namespace

TEST_CASE("OpenSCAD's OFF, AMF and 3MF exports import with its volume", "[import][openscad]") {
    if (!have_openscad()) {
        WARN("openscad is not installed: its exports cannot be made");
        return;
    }
    const auto dir = test_dir("import_meshes_openscad");
    const std::string model = write_file(dir / "model.scad", kModel);
    for (const char* ext : {"off", "amf", "3mf"}) {
        INFO(ext);
        const std::string file = std::string("model.") + ext;
        REQUIRE(std::system(("cd '" + dir.string() + "' && openscad -o " + file + " model.scad >/dev/null 2>&1").c_str()) == 0);
        const std::string scene = "import(\"" + file + "\");";
        CHECK(mesh_volume(write_file(dir / "exact.sdl", scene)) == Approx(kModelVolume).epsilon(1e-6));
        check_volume(measure_file(dir, scene, "scene.sdl"), kModelVolume, 1e-3);
        check_volume(measure_file(dir, scene, "scene.scad"), kModelVolume, 1e-3);
        CHECK(openscad_volume(dir, scene) == Approx(kModelVolume).epsilon(1e-5));
    }
}

TEST_CASE("OFF prisms with concave and non-planar faces have the closed form's volume", "[import]") {
    const auto dir = test_dir("import_meshes_concave");
    write_file(dir / "l.off", l_prism(0));
    write_file(dir / "lifted.off", l_prism(0.5));
    check_volume(measure_file(dir, "import(\"l.off\");", "scene.sdl"), 4, 1e-3);
    // The lifted corner's ear (3, 0), (3, 1), (1, 1) of area 1 rises by
    // 0.5 at one corner: 4 + 1 · 0.5 / 3. OpenSCAD cuts the face the same way.
    const Measured m = measure_file(dir, "import(\"lifted.off\");", "scene.sdl");
    check_volume(m, 4 + 0.5 / 3, 1e-3);
    if (const double ref = openscad_volume(dir, "import(\"lifted.off\");"); std::isfinite(ref)) {
        CHECK(ref == Approx(4 + 0.5 / 3).epsilon(1e-6));
        CHECK(openscad_volume(dir, "import(\"l.off\");") == Approx(4).epsilon(1e-6));
    }
}

TEST_CASE("an AMF in inches is 25.4 mm a unit in .sdl and 1 mm in .scad, as OpenSCAD reads it", "[import]") {
    const auto dir = test_dir("import_meshes_units");
    std::string amf = "<?xml version=\"1.0\"?>\n<amf unit=\"inch\"><object id=\"0\"><mesh><vertices>\n";
    const int corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& c : corners)
        amf += "<vertex><coordinates><x>" + std::to_string(c[0]) + "</x><y>" + std::to_string(c[1]) + "</y><z>" +
               std::to_string(c[2]) + "</z></coordinates></vertex>\n";
    amf += "</vertices><volume>";
    for (const char* t : {"0 2 1", "0 1 3", "0 3 2", "1 2 3"}) {
        int a, b, c;
        std::sscanf(t, "%d %d %d", &a, &b, &c);
        amf += "<triangle><v1>" + std::to_string(a) + "</v1><v2>" + std::to_string(b) + "</v2><v3>" +
               std::to_string(c) + "</v3></triangle>";
    }
    write_file(dir / "tet.amf", amf + "</volume></mesh></object></amf>\n");
    check_volume(measure_file(dir, "import(\"tet.amf\");", "scene.sdl"), 25.4 * 25.4 * 25.4 / 6, 2e-3);
    const Measured scad = measure_file(dir, "import(\"tet.amf\");", "scene.scad");
    check_volume(scad, 1.0 / 6, 2e-3);
    CHECK(scad.err.find("unit=\"inch\" is ignored") != std::string::npos);
    if (const double ref = openscad_volume(dir, "import(\"tet.amf\");"); std::isfinite(ref))
        CHECK(ref == Approx(1.0 / 6).epsilon(1e-6));
}
