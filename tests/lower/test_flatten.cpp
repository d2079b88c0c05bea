// Flattening: nested unions/intersections collapse, difference keeps its
// minuend and a flat subtrahend list, groups and single-child booleans vanish.
#include <catch2/catch.hpp>

#include "tests/lower/graph_builder.hpp"
#include "lower/lower.hpp"
#include "tests/lower/scene_checks.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

// Spheres spaced 3 apart along x never overlap, so nothing gets pruned.
std::uint32_t ball(GraphBuilder& b, int i) { return b.translate({3.0 * i, 0, 0}, b.sphere(1)); }

}  // namespace

TEST_CASE("a lopsided chain of 1000 binary unions becomes one union of 1001 leaves") {
    GraphBuilder b;
    std::uint32_t acc = ball(b, 0);
    for (int i = 1; i <= 1000; ++i) acc = b.uni({acc, ball(b, i)});
    const csg::Scene s = lower_to_csg(b.finish({acc}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 1001);
    CHECK(s.nodes.size() == 1002);
    CHECK(s.leaves.size() == 1001);
    // pre-order keeps the source order of the operands
    for (std::uint32_t k = 0; k < 1001; ++k) {
        const csg::Node& leaf = s.nodes[s.children[s.nodes[0].first + k]];
        CHECK(s.leaves[leaf.first].world_from_object.offset.x == Approx(3.0 * k));
    }
}

TEST_CASE("a deep chain through transforms and groups does not exhaust the stack") {
    GraphBuilder b;
    std::uint32_t acc = b.sphere(1);
    for (int i = 0; i < 100000; ++i) acc = b.translate({1e-5, 0, 0}, b.uni({acc}));
    const csg::Scene s = lower_to_csg(b.finish({acc}));
    REQUIRE(s.nodes.size() == 1);
    CHECK(s.nodes[0].op == csg::Op::Leaf);
    CHECK(s.leaves[0].world_from_object.offset.x == Approx(1.0));
}

TEST_CASE("nested intersections collapse into one, unions inside them stay") {
    GraphBuilder b;
    const auto u = b.uni({b.sphere(1), b.translate({0.5, 0, 0}, b.sphere(1))});
    const auto i = b.inter({b.inter({b.sphere(1.2), b.scale({1, 1, 2}, b.sphere(1))}), b.inter({b.cube(1), u})});
    const csg::Scene s = lower_to_csg(b.finish({i}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Intersection);
    CHECK(s.nodes[0].count == 4);
    CHECK(s.leaves.size() == 5);
    int unions = 0;
    for (const auto& n : s.nodes) unions += n.op == csg::Op::Union;
    CHECK(unions == 1);
}

TEST_CASE("difference keeps its minuend and merges subtrahend unions into one list") {
    GraphBuilder b;
    const auto minuend = b.scale({4, 4, 4}, b.translate({-0.5, -0.5, -0.5}, b.cube(1)));
    const auto sub1 = b.uni({b.sphere(0.5), b.uni({b.translate({1, 0, 0}, b.sphere(0.5)), b.translate({-1, 0, 0}, b.sphere(0.5))})});
    const auto sub2 = b.translate({0, 1, 0}, b.uni({b.sphere(0.3), b.cube(0.2)}));
    const auto d = b.diff({minuend, sub1, sub2, b.translate({0, 0, 1}, b.sphere(0.2))});
    const csg::Scene s = lower_to_csg(b.finish({d}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    REQUIRE(s.nodes[0].count == 7);
    const csg::Node& m = s.nodes[s.children[s.nodes[0].first]];
    REQUIRE(m.op == csg::Op::Leaf);
    CHECK(s.leaves[m.first].kind == csg::PrimKind::Box);
    for (std::uint32_t k = 0; k < 7; ++k) CHECK(s.nodes[s.children[s.nodes[0].first + k]].op == csg::Op::Leaf);
}

TEST_CASE("a difference used as a minuend merges: (a - b) - c = a - b - c") {
    GraphBuilder b;
    const auto inner = b.diff({b.sphere(1), b.scale({0.9, 0.9, 0.9}, b.sphere(1))});
    const auto outer = b.diff({inner, b.translate({0, 0, 1}, b.cylinder(-0.5, 0.5, 0.3, 0.3))});
    const csg::Scene s = lower_to_csg(b.finish({outer}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 3);
    CHECK(s.leaves.size() == 3);
    CHECK(s.leaves[0].kind == csg::PrimKind::Sphere);
    CHECK(s.leaves[0].p[0] == 1);
}

TEST_CASE("groups, transforms, appearances and single-child booleans disappear") {
    GraphBuilder b;
    const auto leaf = b.inter({b.diff({b.uni({b.color({1, 0, 0}, b.translate({1, 2, 3}, b.uni({b.sphere(2)})))})})});
    const csg::Scene s = lower_to_csg(b.finish({b.uni({leaf})}));
    test::check_structure(s);
    REQUIRE(s.nodes.size() == 1);
    CHECK(s.nodes[0].op == csg::Op::Leaf);
    CHECK(s.nodes[0].parent == csg::kNone);
    CHECK(s.leaves[0].bounds.lo == glm::dvec3(-1, 0, 1));
    CHECK(s.leaves[0].bounds.hi == glm::dvec3(3, 4, 5));
}

TEST_CASE("a union under a transform inside a union is merged into the outer union") {
    GraphBuilder b;
    const auto inner = b.rotate(30, {0, 0, 1}, b.uni({ball(b, 1), ball(b, 2)}));
    const csg::Scene s = lower_to_csg(b.finish({ball(b, 0), inner, b.uni({ball(b, 5), b.uni({ball(b, 6)})})}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 5);
}

TEST_CASE("the root's bounds are the union of its operands' boxes") {
    GraphBuilder b;
    const csg::Scene s = lower_to_csg(b.finish({ball(b, 0), ball(b, 3)}));
    CHECK(s.bounds().lo == glm::dvec3(-1, -1, -1));
    CHECK(s.bounds().hi == glm::dvec3(10, 1, 1));
}
