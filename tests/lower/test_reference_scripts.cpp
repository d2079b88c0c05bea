// The docs/spec.md §9 reference models as shipped in examples/*.sdl, through the
// parser and evaluator, lower to the expected flattened shapes.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "csg/dump.hpp"
#include "csg/membership.hpp"
#include "tests/lower/scene_checks.hpp"

using namespace kerf;

namespace {

csg::Scene lower_example(const std::string& name, EvalOptions options = {}) {
    options.echo = [](const std::string&) {};
    return lower_to_csg(evaluate_file(std::string(KERF_SOURCE_DIR) + "/examples/" + name, options).graph);
}

int children_with_op(const csg::Scene& s, csg::Op op) {
    int n = 0;
    const csg::Node& root = s.nodes[s.root];
    for (std::uint32_t k = 0; k < root.count; ++k) n += s.nodes[s.children[root.first + k]].op == op;
    return n;
}

}  // namespace

TEST_CASE("examples/large_shell.sdl: one union of 65 differences with 195 leaves") {
    const csg::Scene s = lower_example("large_shell.sdl");
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 65);
    CHECK(children_with_op(s, csg::Op::Difference) == 65);
    CHECK(s.leaves.size() == 195);
}

TEST_CASE("examples/small_shell.sdl: one union of 16 differences") {
    const csg::Scene s = lower_example("small_shell.sdl");
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 16);
    CHECK(children_with_op(s, csg::Op::Difference) == 16);
    CHECK(s.leaves.size() == 64);
}

TEST_CASE("examples/checkered_cube.sdl: one difference, a minuend and 150 subtrahends") {
    const csg::Scene s = lower_example("checkered_cube.sdl");
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 151);
    CHECK(s.nodes[0].bounds.lo.x == Approx(-1.1));
    CHECK(s.nodes[0].bounds.hi.z == Approx(1.1));
    CHECK(s.materials.size() == 2);
    CHECK(s.materials[1].interior != s.materials[1].color);
}

TEST_CASE("examples/grooved_sphere.sdl: a sphere minus 6 tori") {
    const csg::Scene s = lower_example("grooved_sphere.sdl");
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    REQUIRE(s.nodes[0].count == 7);
    CHECK(s.leaves[0].kind == csg::PrimKind::Sphere);
    for (int i = 1; i < 7; ++i) {
        CHECK(s.leaves[i].kind == csg::PrimKind::Torus);
        // every groove is a 0.9-scaled torus 0.374 from the centre: its box
        // reaches 0.374 + 0.09 along the axis it was moved along
        const csg::Aabb& b = s.leaves[i].bounds;
        const double reach = std::max({-b.lo.x, b.hi.x, -b.lo.y, b.hi.y, -b.lo.z, b.hi.z});
        CHECK(reach == Approx(0.99));
    }
}

TEST_CASE("examples/fishbowl.sdl, lens.sdl: shapes") {
    const csg::Scene bowl = lower_example("fishbowl.sdl");
    test::check_structure(bowl);
    REQUIRE(bowl.nodes[0].op == csg::Op::Difference);
    CHECK(bowl.nodes[0].count == 3);
    CHECK(bowl.leaves[2].kind == csg::PrimKind::Cylinder);
    CHECK(bowl.leaves[2].bounds.lo.z == Approx(0).margin(1e-9));  // the cone's apex at the centre
    const csg::Scene lens = lower_example("lens.sdl");
    REQUIRE(lens.nodes[0].op == csg::Op::Intersection);
    CHECK(lens.nodes[0].bounds.hi.z == Approx(0.4));
}

TEST_CASE("examples/holes.sdl: n = 40 gives 1600 holes, -D n=10 gives 100") {
    const csg::Scene s = lower_example("holes.sdl");
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 1601);
    EvalOptions small;
    small.defines = {{"n", "10"}};
    const csg::Scene t = lower_example("holes.sdl", small);
    REQUIRE(t.nodes[0].op == csg::Op::Difference);
    CHECK(t.nodes[0].count == 101);
}

TEST_CASE("every example has its own camera and lights, and dumps") {
    for (const char* name : {"grooved_sphere.sdl", "checkered_cube.sdl", "small_shell.sdl", "large_shell.sdl",
                             "fishbowl.sdl", "lens.sdl", "holes.sdl"}) {
        INFO(name);
        const csg::Scene s = lower_example(name);
        CHECK(s.lights.size() == 2);
        CHECK(s.camera.position != glm::dvec3(0, -10, 5));  // not the struct default
        const std::string text = csg::dump_scene(s);
        CHECK(text.find(std::string("examples/") + name) != std::string::npos);
    }
}

TEST_CASE("examples/gear.sdl: teeth, bore, keyway and lightening holes where the profile puts them") {
    const csg::Scene s = lower_example("gear.sdl");
    test::check_structure(s);
    auto at = [](double r, double deg, double z) {
        const double a = deg * M_PI / 180;
        return glm::dvec3(r * std::cos(a), r * std::sin(a), z);
    };
    const double tooth = 360.0 * 0.3 / 24, gap = 360.0 * 0.8 / 24;  // middle of tooth 0 and of the gap after it
    CHECK(csg::contains(s, at(10.3, tooth, 2)));      // a tooth near its tip
    CHECK_FALSE(csg::contains(s, at(10.3, gap, 2)));  // between two teeth
    CHECK(csg::contains(s, at(8.5, gap, 2)));         // below the root circle
    CHECK_FALSE(csg::contains(s, at(2.9, 90, 2)));    // the bore
    CHECK_FALSE(csg::contains(s, {3.5, 0, 2}));       // the keyway
    CHECK(csg::contains(s, at(4, 30, 2)));             // the web between the holes
    CHECK_FALSE(csg::contains(s, at(6, 60, 2)));       // a lightening hole
    CHECK_FALSE(csg::contains(s, at(8.5, gap, 4.01))); // above the top
}

TEST_CASE("examples/vase.sdl: the wall where the profile puts it, the quarter after 270 degrees open") {
    const csg::Scene s = lower_example("vase.sdl");
    // At z = 6 the profile's outer radius is 3 + 1.6·sin 90° = 4.6, the wall 0.4 thick.
    auto at = [](double deg, double rho, double z) {
        return glm::dvec3(rho * std::cos(deg * M_PI / 180), rho * std::sin(deg * M_PI / 180), z);
    };
    CHECK(csg::contains(s, at(90, 4.4, 6)));
    CHECK(csg::contains(s, at(200, 4.4, 6)));
    CHECK_FALSE(csg::contains(s, at(90, 4.7, 6)));
    CHECK_FALSE(csg::contains(s, at(90, 4.1, 6)));
    CHECK_FALSE(csg::contains(s, at(315, 4.4, 6)));  // the open quarter
    CHECK(csg::contains(s, at(45, 1, 0.3)));         // the foot
    CHECK(s.bounds().lo.z == 0);
}
