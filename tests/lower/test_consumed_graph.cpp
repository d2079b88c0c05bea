// lower_to_csg of a graph the caller gives up (an rvalue) frees the graph's
// nodes, child lists and transforms before it writes the scene's nodes
// (docs/performance.md, "Memory"); the scene must be the one the graph
// kept alive gives, dump for dump, and its errors located the same.
#include <catch2/catch.hpp>

#include <string>

#include "csg/dump.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

std::string error_text(const std::function<void()>& run) {
    try {
        run();
    } catch (const SourceError& e) {
        return format_diagnostic(e.diagnostic());
    }
    return "no error";
}

}  // namespace

TEST_CASE("a consumed graph lowers to the same scene and is emptied") {
    const char* scripts[] = {
        // a loop of translated leaves under one material, with a pattern
        "material(color = \"red\", pattern = \"checker\", pattern_scale = 0.5)\n"
        "    for (i = [0:20]) translate([i, 0, 0]) rotate([0, 0, 7 * i]) cube([0.8, 0.5, 0.3]);\n",
        // differences, intersections, a half-space, a duplicate, a mesh and a prism
        "difference() { sphere(2); translate([1, 0, 0]) sphere(1); translate([1, 0, 0]) sphere(1); }\n"
        "intersection() { cube(3, center = true); rotate([10, 20, 30]) cylinder(h = 4, r = 1, center = true); }\n"
        "translate([5, 0, 0]) polyhedron([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], [[0,2,1],[0,1,3],[1,2,3],[0,3,2]]);\n"
        "translate([0, 5, 0]) linear_extrude(2) polygon([[0,0],[2,0],[1,2]]);\n",
        // hull() and minkowski(): lowering resolves them into a copy of the graph first
        "hull() { sphere(1); translate([3, 0, 0]) cube(1); }\n"
        "translate([0, 6, 0]) minkowski() { cube(1); sphere(0.2); }\n",
        // nothing at all
        "",
    };
    for (const char* text : scripts) {
        INFO(text);
        const EvalResult kept = test::evaluated(text);
        EvalResult given = test::evaluated(text);
        const std::string want = csg::dump_scene(lower_to_csg(kept.graph));
        const std::string got = csg::dump_scene(lower_to_csg(std::move(given.graph)));
        CHECK(got == want);
        CHECK(given.graph.nodes.empty());
        CHECK(given.graph.child_refs.empty());
        CHECK(given.graph.matrices.empty());
        CHECK(given.graph.materials.size() == kept.graph.materials.size());
    }
}

TEST_CASE("a consumed graph's errors point where the kept graph's do") {
    const char* scripts[] = {
        // two fine scales composing to a singular one: the leaf's error
        "sphere(1);\nscale(1e-200) scale(1e-200)\n  sphere(1);\n",
        // deeper than csg::kMaxDepth: located at the node past it (the emitter's error)
        "module m(n) { if (n > 0) difference() { sphere(2); difference() { sphere(2); difference() { sphere(2);\n"
        "difference() { sphere(2); difference() { sphere(2); m(n - 1); } } } } } }\nm(900);\n",
    };
    for (const char* text : scripts) {
        INFO(text);
        const std::string want = error_text([&] {
            const EvalResult kept = test::evaluated(text);
            lower_to_csg(kept.graph);
        });
        const std::string got = error_text([&] {
            EvalResult given = test::evaluated(text);
            lower_to_csg(std::move(given.graph));
        });
        CHECK(want.find("error:") != std::string::npos);
        CHECK(got == want);
    }
}
