// Identical leaves of one operation are one operand (lower/duplicate_leaves.*,
// docs/lowering.md): the lowered solid is the same point by point
// (csg::contains, the membership oracle) as the scene written without the
// copies, and the leaf count drops to that scene's.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "csg/membership.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/patterns.hpp"
#include "tests/lower/graph_builder.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

// copies = 1: the scene as written once; more: every leaf repeated. Copies
// of a leaf under a different transform or colour are different leaves.
csg::Scene scene_with(int copies) {
    GraphBuilder b;
    auto many = [&](auto make) {
        std::vector<std::uint32_t> v;
        for (int i = 0; i < copies; ++i) v.push_back(make());
        return v;
    };
    std::vector<std::uint32_t> uni = many([&] { return b.sphere(1); });
    uni.push_back(b.translate({0.5, 0, 0}, b.sphere(1)));  // not a copy: moved
    std::vector<std::uint32_t> inter = many([&] { return b.translate({2, 0, 0}, b.cube(1)); });
    inter.push_back(b.translate({2.5, 0, 0}, b.sphere(0.8)));
    std::vector<std::uint32_t> diff{b.translate({-2, 0, 0}, b.cube(1.5))};
    for (std::uint32_t s : many([&] { return b.translate({-2, 0, 0}, b.sphere(0.9)); })) diff.push_back(s);
    diff.push_back(b.translate({-2, 0, 0}, b.cube(1.5)));  // equal to the minuend: A − A stays (empty)
    std::vector<std::uint32_t> coloured = many([&] { return b.translate({0, 3, 0}, b.sphere(0.5)); });
    coloured.push_back(b.color({1, 0, 0}, b.translate({0, 3, 0}, b.sphere(0.5))));  // other material
    return lower_to_csg(b.finish({b.uni(uni), b.inter(inter), b.diff(diff), b.uni(coloured)}));
}

}  // namespace

TEST_CASE("duplicate leaves are dropped and the solid is unchanged") {
    const csg::Scene once = scene_with(1), many = scene_with(5);
    CHECK(many.leaves.size() == once.leaves.size());
    CHECK(once.leaves.size() == 9);  // 2 + 2 + 3 + 2
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-4, 4);
    for (int i = 0; i < 200000; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        REQUIRE(csg::contains(many, p) == csg::contains(once, p));
    }
}

// Prisms with the same slab and transform but other sections are different
// leaves (the section is Leaf::polygon): merging them lost a shape.
TEST_CASE("prisms of different sections are not duplicates") {
    auto f = std::make_shared<kerf::SourceFile>();
    f->path = "prisms.sdl";
    f->text = "linear_extrude(1) polygon([[0,0],[2,0],[0,2]]);\n"
              "linear_extrude(1) polygon([[0,0],[2,0],[2,2]]);\n";
    const kerf::csg::Scene s = kerf::lower_to_csg(kerf::evaluate_source(f).graph);
    CHECK(s.leaves.size() == 2);
    CHECK(kerf::csg::contains(s, {0.2, 1.5, 0.5}));  // only in the first triangle
    CHECK(kerf::csg::contains(s, {1.8, 1.5, 0.5}));  // only in the second
}

// The same sphere under one patterned material, once with the material()
// call at the world origin and once inside translate([0.5, 0, 0]) (the
// sphere moved back inside it): the same bits but for the pattern frame, so
// two leaves whose checkers are half a cell apart. Merging them (the frame
// was once left out of the comparison) painted both with the first's.
TEST_CASE("leaves differing only in pattern frame are not duplicates, equal frames are shared") {
    GraphBuilder b;
    csg::Material m;
    m.color = {1, 1, 1};
    m.color2 = {0, 0, 0};
    m.pattern = csg::Pattern::Checker;
    const std::uint32_t checker = b.material(m);
    auto shifted = [&] { return b.translate({0.5, 0, 0}, b.appearance(checker, b.translate({-0.5, 0, 0}, b.sphere(1)))); };
    const csg::Scene s = lower_to_csg(b.finish({b.uni({b.appearance(checker, b.sphere(1)), shifted(), shifted()})}));
    REQUIRE(s.leaves.size() == 2);  // the third is the second again
    CHECK(s.leaves[0].object_from_world.offset == s.leaves[1].object_from_world.offset);
    // One frame per distinct call space: the identity and the shift.
    REQUIRE(s.material_frames.size() == 2);
    // The closed form: the cell of q under the call at x = 0.5 is the one of q − (0.5, 0, 0).
    for (double x : {0.2, 0.7, 1.3}) {
        const glm::dvec3 q(x, 0.3, 0.4);
        const auto cell = [](const glm::dvec3& p) { return int(std::floor(p.x) + std::floor(p.y) + std::floor(p.z)) & 1; };
        CHECK(render::pattern_color(s.materials[s.leaves[0].material], s.material_frames[s.leaves[0].material_frame], q).x ==
              (cell(q) ? 0 : 1));
        CHECK(render::pattern_color(s.materials[s.leaves[1].material], s.material_frames[s.leaves[1].material_frame], q).x ==
              (cell(q - glm::dvec3(0.5, 0, 0)) ? 0 : 1));
    }
}

// A union whose list is one inner union's, spliced whole, keeps its leaves
// without a second look (flat_tree.cpp, Frame::distinct); one that gains
// anything beside it looks again, whichever side the copy is on.
TEST_CASE("duplicates across nested unions are dropped, a spliced union is not looked at twice") {
    const auto leaves_of = [](const char* text) {
        auto f = std::make_shared<kerf::SourceFile>();
        f->path = "nested.sdl";
        f->text = text;
        return kerf::lower_to_csg(kerf::evaluate_source(f).graph).leaves.size();
    };
    CHECK(leaves_of("union() { union() { sphere(1); sphere(2); } sphere(1); }") == 2);
    CHECK(leaves_of("union() { sphere(1); union() { sphere(1); sphere(2); } }") == 2);
    CHECK(leaves_of("union() { union() { sphere(1); sphere(2); } union() { sphere(2); sphere(3); } }") == 3);
    CHECK(leaves_of("union() { union() { sphere(1); sphere(2); } translate([0, 0, 0]) sphere(2); }") == 2);
    CHECK(leaves_of("color(\"red\") union() { union() { for (i = [0:2]) sphere(1 + i % 2); } }") == 2);
    CHECK(leaves_of("union() { union() { for (i = [0:3]) sphere(1 + i % 2); } for (i = [0:3]) sphere(1 + i % 3); }") == 3);
}
