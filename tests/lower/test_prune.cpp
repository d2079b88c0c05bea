// Pruning and empty-solid rules (docs/spec.md §4, architecture "model only what the
// scene requires").
#include <catch2/catch.hpp>

#include "tests/lower/graph_builder.hpp"
#include "lower/lower.hpp"
#include "tests/lower/scene_checks.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

TEST_CASE("subtrahends whose boxes miss the minuend are dropped") {
    GraphBuilder b;
    const auto d = b.diff({b.sphere(1), b.translate({0.5, 0, 0}, b.sphere(0.7)), b.translate({5, 0, 0}, b.sphere(1)),
                           b.uni({b.translate({0, -3, 0}, b.cube(1)), b.translate({0, 0, 0.9}, b.cube(0.2))})});
    const csg::Scene s = lower_to_csg(b.finish({d}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 3);
    CHECK(s.leaves.size() == 3);
    CHECK(s.nodes[0].bounds.hi == glm::dvec3(1, 1, 1));  // the minuend's box
}

TEST_CASE("a difference whose subtrahends all miss becomes its minuend, merged into the parent union") {
    GraphBuilder b;
    const auto d = b.diff({b.uni({b.sphere(1), b.translate({2, 0, 0}, b.sphere(1))}), b.translate({0, 9, 0}, b.sphere(1))});
    const csg::Scene s = lower_to_csg(b.finish({d, b.translate({0, 0, 5}, b.sphere(1))}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Union);
    CHECK(s.nodes[0].count == 3);
}

TEST_CASE("empty intersections are removed") {
    GraphBuilder b;
    const auto disjoint = b.inter({b.sphere(1), b.translate({3, 0, 0}, b.sphere(1))});
    const auto kept = b.translate({0, 5, 0}, b.cube(1));
    const csg::Scene s = lower_to_csg(b.finish({disjoint, kept}));
    test::check_structure(s);
    REQUIRE(s.nodes.size() == 1);
    CHECK(s.leaves[0].kind == csg::PrimKind::Box);

    GraphBuilder b2;
    const csg::Scene only = lower_to_csg(b2.finish({b2.inter({b2.sphere(1), b2.translate({3, 0, 0}, b2.sphere(1))})}));
    CHECK(only.root == csg::kNone);
    CHECK(only.nodes.empty());
    CHECK(only.leaves.empty());
}

TEST_CASE("an intersection's box is the overlap of its operands' boxes") {
    GraphBuilder b;
    const csg::Scene s = lower_to_csg(b.finish({b.inter({b.sphere(1), b.translate({1.5, 0, 0}, b.sphere(1))})}));
    REQUIRE(s.nodes[0].op == csg::Op::Intersection);
    CHECK(s.nodes[0].bounds.lo == glm::dvec3(0.5, -1, -1));
    CHECK(s.nodes[0].bounds.hi == glm::dvec3(1, 1, 1));
}

TEST_CASE("A - A is kept: showing it empty is the renderer's job") {
    GraphBuilder b;
    const csg::Scene s = lower_to_csg(b.finish({b.diff({b.sphere(1), b.sphere(1)})}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    CHECK(s.nodes[0].count == 2);
}

TEST_CASE("empty operations follow docs/spec.md §4") {
    SECTION("union(), intersection(), difference() with no children are empty") {
        for (auto k : {graph::NodeKind::Union, graph::NodeKind::Intersection, graph::NodeKind::Difference}) {
            GraphBuilder b;
            const csg::Scene s = lower_to_csg(b.finish({b.op(k, {})}));
            CHECK(s.root == csg::kNone);
        }
    }
    SECTION("an intersection with an empty child is empty") {
        GraphBuilder b;
        const csg::Scene s = lower_to_csg(b.finish({b.inter({b.sphere(1), b.uni({}), b.sphere(0.5)})}));
        CHECK(s.root == csg::kNone);
    }
    SECTION("a difference with an empty minuend is empty") {
        GraphBuilder b;
        const csg::Scene s = lower_to_csg(b.finish({b.diff({b.inter({}), b.sphere(1)})}));
        CHECK(s.root == csg::kNone);
    }
    SECTION("an empty subtrahend disappears") {
        GraphBuilder b;
        const csg::Scene s = lower_to_csg(b.finish({b.diff({b.sphere(1), b.uni({}), b.sphere(0.5)})}));
        REQUIRE(s.nodes[0].op == csg::Op::Difference);
        CHECK(s.nodes[0].count == 2);
    }
    SECTION("an empty top level gives a scene without solids but with a camera and lights") {
        GraphBuilder b;
        const csg::Scene s = lower_to_csg(b.finish({}));
        CHECK(s.root == csg::kNone);
        CHECK(s.lights.size() == 2);
        CHECK(s.materials.size() == 1);
    }
}

TEST_CASE("half-spaces: an intersection with a bounded solid is bounded") {
    GraphBuilder b;
    // sphere ∩ {z <= 0.5}
    const csg::Scene s = lower_to_csg(b.finish({b.inter({b.plane({0, 0, 1}, 0.5), b.sphere(1)})}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Intersection);
    CHECK(s.nodes[0].bounds.lo == glm::dvec3(-1, -1, -1));
    CHECK(s.nodes[0].bounds.hi == glm::dvec3(1, 1, 0.5));
    const csg::Leaf& plane = s.leaves[0];
    CHECK(plane.kind == csg::PrimKind::Plane);
    CHECK(std::isinf(plane.bounds.lo.z));
    CHECK(plane.bounds.hi.z == 0.5);
}

TEST_CASE("half-spaces: a tilted plane clips an intersection's box exactly") {
    // unit cube ∩ {x + y <= 0.5}: x and y run up to 0.5 at most.
    GraphBuilder b;
    const auto top = b.inter({b.cube(1), b.plane(glm::normalize(glm::dvec3(1, 1, 0)), 0.5 / std::sqrt(2.0))});
    const csg::Scene s = lower_to_csg(b.finish({top}));
    CHECK(s.nodes[0].bounds.hi.x == Approx(0.5));
    CHECK(s.nodes[0].bounds.hi.y == Approx(0.5));
    CHECK(s.nodes[0].bounds.hi.z == Approx(1));
    CHECK(s.nodes[0].bounds.lo.x == Approx(0).margin(1e-15));
}

TEST_CASE("half-spaces: subtracting a plane clips the difference's box, a plane above everything removes it") {
    GraphBuilder b;
    // transformed plane: the normal (0,0,1) rotated to -x: half-space x >= -0.25... then subtracted
    const auto cut = b.diff({b.sphere(1), b.translate({0.25, 0, 0}, b.rotate(-90, {0, 1, 0}, b.plane({0, 0, 1}, 0)))});
    const csg::Scene s = lower_to_csg(b.finish({cut}));
    REQUIRE(s.nodes[0].op == csg::Op::Difference);
    // rotating (0,0,1) by -90° about y gives (-1,0,0): the plane keeps x >= 0.25,
    // subtracting it leaves x <= 0.25.
    CHECK(s.nodes[0].bounds.hi.x == Approx(0.25));
    CHECK(s.nodes[0].bounds.lo.x == Approx(-1));

    GraphBuilder b2;
    const auto gone = b2.diff({b2.sphere(1), b2.plane({0, 0, 1}, 2)});
    CHECK(lower_to_csg(b2.finish({gone})).root == csg::kNone);
}

TEST_CASE("a plane at the top level makes the root unbounded, the camera frames the bounded leaves") {
    GraphBuilder b;
    // The plain look's camera looks at the framing box's centre (the studio
    // one frames the same box: test_studio.cpp).
    const csg::Scene s = lower_to_csg(b.finish({b.plane({0, 0, 1}, -1), b.translate({10, 0, 0}, b.sphere(1))}), {Look::Plain});
    CHECK(std::isinf(s.bounds().lo.x));
    CHECK(s.camera.look_at.x == Approx(10));
    CHECK(s.camera.look_at.z == Approx(0));
}

TEST_CASE("meshes: only used ones are set up, each once however many leaves use it") {
    GraphBuilder b;
    graph::PolygonMesh tet;
    tet.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // OpenSCAD order: clockwise seen from outside.
    tet.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    graph::PolygonMesh quad = tet;
    quad.faces.push_back({0, 1, 2, 3});
    b.g.meshes = {quad, tet};
    const auto top = b.uni({b.mesh(1), b.translate({3, 0, 0}, b.mesh(1)), b.inter({b.mesh(0), b.translate({9, 0, 0}, b.mesh(0))})});
    const csg::Scene s = lower_to_csg(b.finish({top}));
    REQUIRE(s.meshes.size() == 1);
    CHECK(s.meshes[0].triangles.size() == 12);
    CHECK(s.leaves.size() == 2);
    CHECK(s.leaves[0].mesh == 0);
    CHECK(s.leaves[1].mesh == 0);
    CHECK(s.leaves[1].bounds.lo == glm::dvec3(3, 0, 0));
    CHECK(s.leaves[1].bounds.hi == glm::dvec3(4, 1, 1));
    // Winding becomes counter-clockwise from outside: the face normal points out.
    const auto& m = s.meshes[0];
    const glm::dvec3 centroid(0.25);
    for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
        const glm::dvec3 a = m.points[m.triangles[t]], bb = m.points[m.triangles[t + 1]], c = m.points[m.triangles[t + 2]];
        CHECK(glm::dot(glm::cross(bb - a, c - a), a - centroid) > 0);
    }
}

TEST_CASE("union members outside an intersection's box are dropped") {
    GraphBuilder b;
    // (a row of 5 spheres along x) ∩ (a box around the first two)
    std::vector<std::uint32_t> row;
    for (int i = 0; i < 5; ++i) row.push_back(b.translate({3.0 * i, 0, 0}, b.sphere(1)));
    const auto top = b.inter({b.uni(row), b.box({-1, -1, -1}, {4, 1, 1})});
    const csg::Scene s = lower_to_csg(b.finish({top}));
    test::check_structure(s);
    REQUIRE(s.nodes[0].op == csg::Op::Intersection);
    const csg::Node& u = s.nodes[s.children[s.nodes[0].first]];
    REQUIRE(u.op == csg::Op::Union);
    CHECK(u.count == 2);
    CHECK(u.bounds.hi.x == 4);
    CHECK(s.leaves.size() == 3);

    SECTION("a union trimmed to one intersection member is merged into the intersection") {
        GraphBuilder c;
        const auto lens = c.inter({c.sphere(1), c.translate({0.5, 0, 0}, c.sphere(1))});
        const auto far = c.translate({10, 0, 0}, c.sphere(1));
        const csg::Scene t = lower_to_csg(c.finish({c.inter({c.uni({lens, far}), c.cube(1)})}));
        test::check_structure(t);
        REQUIRE(t.nodes[0].op == csg::Op::Intersection);
        CHECK(t.nodes[0].count == 3);
    }
    SECTION("a union with no member inside the box makes the intersection empty") {
        GraphBuilder c;
        // two spheres whose union box covers the cube but neither sphere's box does
        const auto pair = c.uni({c.translate({-3, 0, 0}, c.sphere(1)), c.translate({3, 0, 0}, c.sphere(1))});
        const csg::Scene t = lower_to_csg(c.finish({c.inter({pair, c.box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5})})}));
        CHECK(t.root == csg::kNone);
    }
}

TEST_CASE("half-spaces that cannot change the result are dropped") {
    SECTION("a tilted half-space subtracted far from the minuend") {
        GraphBuilder b;
        // {x + y <= -10}: its box is unbounded, but it misses the unit sphere
        const auto top = b.diff({b.sphere(1), b.plane(glm::normalize(glm::dvec3(1, 1, 0)), -10), b.sphere(0.5)});
        const csg::Scene s = lower_to_csg(b.finish({top}));
        REQUIRE(s.nodes[0].op == csg::Op::Difference);
        CHECK(s.nodes[0].count == 2);
        CHECK(s.leaves[1].kind == csg::PrimKind::Sphere);
    }
    SECTION("a half-space containing an intersection's whole box") {
        GraphBuilder b;
        const auto top = b.inter({b.sphere(1), b.plane(glm::normalize(glm::dvec3(1, 1, 1)), 5), b.translate({0.5, 0, 0}, b.sphere(1))});
        const csg::Scene s = lower_to_csg(b.finish({top}));
        REQUIRE(s.nodes[0].op == csg::Op::Intersection);
        CHECK(s.nodes[0].count == 2);
        for (const auto& l : s.leaves) CHECK(l.kind == csg::PrimKind::Sphere);
    }
    SECTION("a half-space cutting the box is kept") {
        GraphBuilder b;
        const auto top = b.inter({b.sphere(1), b.plane(glm::normalize(glm::dvec3(1, 1, 1)), 0.2)});
        const csg::Scene s = lower_to_csg(b.finish({top}));
        REQUIRE(s.nodes[0].op == csg::Op::Intersection);
        CHECK(s.nodes[0].count == 2);
    }
}
