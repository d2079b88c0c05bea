// The docs/spec.md §9 reference models built by hand as scene graphs (what the
// evaluator should produce for examples/*.sdl), lowered to the expected
// flattened shapes. reference_scripts_test.cpp checks the same shapes
// through the parser and evaluator.
#include <catch2/catch.hpp>

#include <cmath>

#include "tests/lower/graph_builder.hpp"
#include "lower/lower.hpp"
#include "tests/lower/scene_checks.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

const glm::dvec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

int count_children_of_op(const csg::Scene& s, std::uint32_t node, csg::Op op) {
    int n = 0;
    for (std::uint32_t k = 0; k < s.nodes[node].count; ++k) n += s.nodes[s.children[s.nodes[node].first + k]].op == op;
    return n;
}

}  // namespace

TEST_CASE("grooved sphere: a sphere minus 6 tori") {
    GraphBuilder b;
    auto groove = [&] { return b.translate({0, 0, 0.374}, b.scale(glm::dvec3(0.9), b.torus(1, 0.1))); };
    auto pair = [&] { return b.uni({groove(), b.rotate(180, kY, groove())}); };
    const auto model = b.diff({b.sphere(1), pair(), b.rotate(90, kY, pair()), b.rotate(90, kX, pair())});
    const csg::Scene s = lower_to_csg(b.finish({model}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    REQUIRE(s.nodes[0].count == 7);
    CHECK(s.leaves[0].kind == csg::PrimKind::Sphere);
    for (int i = 1; i < 7; ++i) CHECK(s.leaves[i].kind == csg::PrimKind::Torus);
    // the first groove: R = 0.9, r = 0.09 around z = 0.374
    CHECK(s.leaves[1].bounds.hi.z == Approx(0.374 + 0.09));
    CHECK(s.leaves[1].bounds.hi.x == Approx(0.99));
}

TEST_CASE("checkered cube: one difference, a minuend and 150 subtrahends") {
    GraphBuilder b;
    auto small = [&] { return b.translate({0.8, 0.8, 1.1}, b.scale(glm::dvec3(0.2), b.translate(glm::dvec3(-0.5), b.cube(1)))); };
    auto grid = [&] {
        std::vector<std::uint32_t> rows;
        for (int j = 0; j < 5; ++j) {
            std::vector<std::uint32_t> row;
            for (int k = 0; k < 5; ++k) row.push_back(b.translate({-0.4 * k, 0, 0}, small()));
            rows.push_back(b.translate({0, -0.4 * j, 0}, b.uni(row)));
        }
        return b.uni(rows);
    };
    std::vector<std::uint32_t> lattice;
    for (double a : {0.0, 90.0, 180.0, 270.0}) lattice.push_back(b.rotate(a, kX, grid()));
    for (double a : {90.0, 270.0}) lattice.push_back(b.rotate(a, kY, grid()));
    const auto big = b.scale(glm::dvec3(2.2), b.translate(glm::dvec3(-0.5), b.cube(1)));
    std::vector<std::uint32_t> kids{big};
    kids.push_back(b.uni(lattice));
    const csg::Scene s = lower_to_csg(b.finish({b.diff(kids)}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 151);
    CHECK(s.leaves.size() == 151);
    CHECK(s.nodes[0].bounds.lo == glm::dvec3(-1.1, -1.1, -1.1));
    // every small cube straddles a face of the big one: half in, half out
    for (std::size_t i = 1; i < s.leaves.size(); ++i) {
        const csg::Aabb& bx = s.leaves[i].bounds;
        double outer = 0;
        for (int a = 0; a < 3; ++a) outer = std::max({outer, std::abs(bx.lo[a]), std::abs(bx.hi[a])});
        CHECK(outer == Approx(1.2));
    }
}

TEST_CASE("small shell: one union of 16 differences of 4 leaves") {
    GraphBuilder b;
    auto segment = [&] {
        return b.diff({b.translate({0, -2, 0}, b.sphere(1)), b.translate({0, -2, 0}, b.scale(glm::dvec3(0.95), b.sphere(1))),
                       b.rotate(18, kZ, b.scale(glm::dvec3(10), b.translate({0, -0.5, -0.5}, b.cube(1)))),
                       b.rotate(162, kZ, b.scale(glm::dvec3(10), b.translate({0, -0.5, -0.5}, b.cube(1))))});
    };
    std::vector<std::uint32_t> segs;
    for (int k = 0; k < 16; ++k) {
        // segment k+1 = segment k : rotZ 22.5° : scale 0.93, built literally as nested transforms
        std::uint32_t seg = segment();
        for (int i = 0; i < k; ++i) seg = b.scale(glm::dvec3(0.93), b.rotate(22.5, kZ, seg));
        segs.push_back(seg);
    }
    const csg::Scene s = lower_to_csg(b.finish(segs));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 16);
    CHECK(count_children_of_op(s, 0, csg::Op::Difference) == 16);
    CHECK(s.leaves.size() == 64);
    // segment 15's minuend: radius 0.93^15 at distance 2·0.93^15 from the axis
    const csg::Node& last = s.nodes[s.children[s.nodes[0].first + 15]];
    const csg::Aabb& m = s.nodes[s.children[last.first]].bounds;
    CHECK((m.hi.z - m.lo.z) / 2 == Approx(std::pow(0.93, 15)));
}

TEST_CASE("large shell: one union of 65 differences with 195 leaves") {
    GraphBuilder b;
    const double sc = 0.989227963463;
    std::vector<std::uint32_t> segs;
    for (int k = 0; k < 65; ++k) {
        std::uint32_t seg = b.translate({3, 0, 0}, b.diff({b.sphere(1), b.scale(glm::dvec3(sc), b.translate({0, -0.02, 0}, b.sphere(1))),
                                                           b.scale(glm::dvec3(sc), b.translate({0, 0.02, 0}, b.sphere(1)))}));
        segs.push_back(b.scale(glm::dvec3(std::pow(0.979, k)), b.rotate(12.0 * k, kZ, seg)));
    }
    const csg::Scene s = lower_to_csg(b.finish({b.uni(segs)}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 65);
    CHECK(count_children_of_op(s, 0, csg::Op::Difference) == 65);
    CHECK(s.leaves.size() == 195);
    const csg::Node& seg1 = s.nodes[s.children[s.nodes[0].first + 1]];
    const double r = 0.979, a = glm::radians(12.0);
    CHECK(seg1.bounds.lo.x == Approx(3 * r * std::cos(a) - r));
    CHECK(seg1.bounds.hi.y == Approx(3 * r * std::sin(a) + r));
}

TEST_CASE("fishbowl: one difference of a sphere, the inner sphere and the cone") {
    GraphBuilder b;
    const auto bowl = b.diff({b.sphere(1), b.scale(glm::dvec3(0.9), b.sphere(1))});
    glm::dmat4 mirror_z(1);
    mirror_z[2][2] = -1;
    const auto cone = b.translate({0, 0, 1.2}, b.xform(mirror_z, b.cylinder(0, 1.2, 0.6, 0)));
    const csg::Scene s = lower_to_csg(b.finish({b.diff({bowl, cone})}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 3);
    CHECK(s.leaves[2].bounds.lo.z == Approx(0).margin(1e-12));
    CHECK(s.leaves[2].bounds.hi.z == Approx(1.2));
    CHECK(s.leaves[2].bounds.hi.x == Approx(0.6));
}

TEST_CASE("lens: an intersection of two spheres, bounded by their overlap") {
    GraphBuilder b;
    const csg::Scene s =
        lower_to_csg(b.finish({b.inter({b.translate({0, 0, -0.6}, b.sphere(1)), b.translate({0, 0, 0.6}, b.sphere(1))})}));
    REQUIRE(s.nodes[0].op == csg::Op::Intersection);
    CHECK(s.nodes[0].bounds.lo.z == Approx(-0.4));
    CHECK(s.nodes[0].bounds.hi.z == Approx(0.4));
}

TEST_CASE("holes: a slab minus n² cylinders") {
    for (int n : {10, 40}) {
        GraphBuilder b;
        std::vector<std::uint32_t> holes;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                holes.push_back(b.translate({(i + 0.5) * 10.0 / n, (j + 0.5) * 10.0 / n, -1}, b.cylinder(0, 3, 0.1, 0.1)));
        const csg::Scene s = lower_to_csg(b.finish({b.diff({b.box({0, 0, 0}, {10, 10, 1}), b.uni(holes)})}));
        test::check_structure(s);
        REQUIRE(s.nodes[0].op == csg::Op::Difference);
        CHECK(s.nodes[0].count == std::uint32_t(n * n + 1));
    }
}
