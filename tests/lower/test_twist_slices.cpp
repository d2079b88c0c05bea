// A twisted or unevenly scaled linear_extrude under --facets openscad is
// OpenSCAD 2021.01's polyhedron of flat slices (docs/openscad.md, "Facets"),
// not kerf's exact sweep. Judged by volume against OpenSCAD's own STL
// export of the same scene, computed once when this test was written:
// `echo 'SCAD' > x.scad; openscad --export-format binstl -o x.stl
// x.scad` (OpenSCAD 2021.01), the
// signed volume of its triangles (tests/cli/test_facets_option.cpp checks
// the same cases against a fresh export through `kerf measure`). The
// mesh's own volume is exact, so the match is to 1e-6 (the binary STL's
// floats keep 7 digits; the ASCII one only 6, too few), and it is a closed mesh: every edge
// is run once each way.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <utility>

#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

struct Solid {
    double volume = 0;
    std::size_t meshes = 0, other_leaves = 0, triangles = 0, unpaired_edges = 0;
    std::string warnings;
};

Solid sliced(const std::string& scad) {
    auto f = std::make_shared<SourceFile>();
    f->path = "test.scad";
    f->text = scad;
    EvalOptions e;
    e.facets = FacetMode::OpenScad;
    const EvalResult r = evaluate_source(f, e);
    Solid s;
    for (const auto& d : r.warnings) s.warnings += d.message + "\n";
    const csg::Scene scene = lower_to_csg(r.graph);
    for (const csg::Leaf& leaf : scene.leaves) {
        if (leaf.kind != csg::PrimKind::Mesh) {
            ++s.other_leaves;
            continue;
        }
        ++s.meshes;
        const csg::Mesh& m = scene.meshes[leaf.mesh];
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> runs;  // directed edge -> (forward - backward) runs
        for (std::size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
            const glm::dvec3 a = leaf.world_from_object.point(m.points[m.triangles[t]]);
            const glm::dvec3 b = leaf.world_from_object.point(m.points[m.triangles[t + 1]]);
            const glm::dvec3 c = leaf.world_from_object.point(m.points[m.triangles[t + 2]]);
            s.volume += glm::dot(a, glm::cross(b, c)) / 6;  // outward (counter-clockwise) winding
            ++s.triangles;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t u = m.triangles[t + k], v = m.triangles[t + (k + 1) % 3];
                if (u < v) ++runs[{u, v}];
                else --runs[{v, u}];
            }
        }
        for (const auto& [edge, balance] : runs) s.unpaired_edges += balance != 0;
    }
    return s;
}

}  // namespace

TEST_CASE("a twisted linear_extrude under --facets openscad has OpenSCAD's volume", "[facets]") {
    const struct {
        const char* scad;
        double volume;  // of OpenSCAD 2021.01's STL export
    } cases[] = {
        {"linear_extrude(10, twist=90) square(5);", 264.6563015},
        {"linear_extrude(10, twist=180, scale=0.5) circle(3, $fn=7);", 148.909771},
        {"linear_extrude(10, twist=45) difference() { square(6, center=true); square(3, center=true); }", 285.8288007},
        {"linear_extrude(8, twist=-120) polygon([[0,0],[6,0],[6,2],[2,2],[2,6],[0,6]]);", 177.5078652},
        // $fn = 0: the defaults $fa = 12, $fs = 2 give 90 slices (three turns).
        {"linear_extrude(20, twist=1080) translate([2,0]) square([3,1]);", 69.6392653},
        {"linear_extrude(10, twist=90, center=true) square(5, center=true);", 268.7287468},
        {"linear_extrude(10, twist=200, $fn=10) square(5);", 282.0830723},
        {"linear_extrude(10, twist=200, scale=[2,0.5], $fs=0.5, $fa=3) square(5);", 273.095868},
        {"linear_extrude(10, scale=[0.3,2]) polygon([[0,0],[5,1],[2,4]]);", 77.30555392},  // no twist: $fs cuts the scale
        {"linear_extrude(10, twist=90, scale=1e-3) square(5);", 85.70979377},
        {"linear_extrude(10, twist=90, scale=1e4) square(5);", 8563305117},
        {"linear_extrude(5, twist=60) union() { square([2,8]); translate([3,0]) difference() { square([4,8]); "
         "translate([1,1]) square([2,2]); translate([1,4]) square([2,2]); } translate([8,2]) circle(1.5, $fn=9); }",
         239.368646},
        {"linear_extrude(10, scale=[0,1], twist=30) polygon([[1,0],[5,1],[2,4]]);", 36.11300669},
        {"linear_extrude(1e-3*10, twist=90) square(1e-3*5);", 2.499999832e-07},  // one slice: $fs is 2
        {"linear_extrude(1e4*10, twist=90) square(1e4*5);", 2.646563034e+14},
        {"linear_extrude(10, twist=90, slices=3) square(5);", 280.5021296},
        {"linear_extrude(10, twist=-90, slices=5) difference() { circle(5, $fn=12); circle(2, $fn=6); }", 650.0565202},
    };
    for (const auto& c : cases) {
        INFO(c.scad);
        const Solid s = sliced(c.scad);
        INFO(s.warnings);
        CHECK(s.warnings.empty());
        CHECK(s.meshes == 1);
        CHECK(s.other_leaves == 0);
        CHECK(s.unpaired_edges == 0);
        CHECK(s.volume == Approx(c.volume).epsilon(1e-6));
    }
}

TEST_CASE("a twist to a zero scale closes its mesh", "[facets]") {
    for (const char* scad : {"linear_extrude(10, scale=[0,1], twist=30) polygon([[1,0],[5,1],[2,4]]);",
                             "linear_extrude(10, scale=0, twist=30) polygon([[1,0],[5,1],[2,4]]);",
                             "linear_extrude(10, scale=[1,0]) polygon([[1,0],[5,1],[2,4]]);"}) {
        INFO(scad);
        const Solid s = sliced(scad);
        CHECK(s.unpaired_edges == 0);
        CHECK(s.volume > 0);
    }
}

TEST_CASE("too many slices are a located error, not exhausted memory", "[facets]") {
    for (const char* scad : {"linear_extrude(10, twist=1e9) square(5);", "linear_extrude(10, twist=90, slices=1e30) square(5);",
                             "linear_extrude(10, twist=90, $fa=0, $fs=0) square(5);"}) {
        INFO(scad);
        CHECK_THROWS_WITH(sliced(scad), Catch::Contains("test.scad:1:1") && Catch::Contains("slices of 4 corners pass the limit"));
    }
}
