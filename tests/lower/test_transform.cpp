// Transforms pushed into the leaves: composition order, inverse, normal
// matrix (outward under mirrors), and located errors for singular maps.
#include <catch2/catch.hpp>

#include "tests/lower/graph_builder.hpp"
#include "lower/lower.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

void check_close(const glm::dvec3& a, const glm::dvec3& b) {
    for (int i = 0; i < 3; ++i) CHECK(a[i] == Approx(b[i]).margin(1e-12));
}

}  // namespace

TEST_CASE("translate(t) rotate(r) s rotates first, then translates (docs/spec.md §4)") {
    GraphBuilder b;
    const auto top = b.translate({10, 0, 0}, b.rotate(90, {0, 0, 1}, b.cube(1)));
    const csg::Scene s = lower_to_csg(b.finish({top}));
    const csg::Leaf& l = s.leaves[0];
    // (1,0,0) rotated 90° about z is (0,1,0), then moved by 10 in x.
    check_close(l.world_from_object.point({1, 0, 0}), {10, 1, 0});
    check_close(l.object_from_world.point({10, 1, 0}), {1, 0, 0});
    check_close(l.bounds.lo, {9, 0, 0});
    check_close(l.bounds.hi, {10, 1, 1});
}

TEST_CASE("object_from_world inverts world_from_object, normal_to_world is its transpose") {
    GraphBuilder b;
    glm::dmat4 shear(1);
    shear[1][0] = 0.7;  // x += 0.7 y
    const auto top = b.scale({2, -1, 0.5}, b.xform(shear, b.rotate(33, {1, 1, 0}, b.torus(1, 0.3))));
    const csg::Scene s = lower_to_csg(b.finish({top}));
    const csg::Leaf& l = s.leaves[0];
    for (glm::dvec3 p : {glm::dvec3(1, 2, 3), glm::dvec3(-0.5, 0.1, 7)}) {
        check_close(l.object_from_world.point(l.world_from_object.point(p)), p);
        check_close(l.world_from_object.point(l.object_from_world.point(p)), p);
    }
    const glm::dmat3 expected = glm::transpose(l.object_from_world.linear);
    for (int r = 0; r < 3; ++r) {
        glm::dvec3 e(0);
        e[r] = 1;
        check_close(l.normal_to_world(e), expected * e);
    }
}

TEST_CASE("normals stay outward under mirrors and negative scales") {
    for (const glm::dvec3 sc : {glm::dvec3(-1, 1, 1), glm::dvec3(1, -2, 1), glm::dvec3(-1, -1, -3), glm::dvec3(2, 3, -0.5)}) {
        GraphBuilder b;
        const csg::Scene s = lower_to_csg(b.finish({b.translate({1, 2, 3}, b.scale(sc, b.sphere(1)))}));
        const csg::Leaf& l = s.leaves[0];
        // On the unit sphere the outward object normal at p is p itself; the
        // world point slightly outside along it must leave the world solid,
        // i.e. the world normal must point away from the world surface point.
        for (glm::dvec3 p : {glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, -2, 0.5)), glm::dvec3(0, 0, -1)}) {
            const glm::dvec3 wp = l.world_from_object.point(p);
            const glm::dvec3 wn = l.normal_to_world(p);
            const glm::dvec3 outside = l.object_from_world.point(wp + 1e-3 * glm::normalize(wn));
            const glm::dvec3 inside = l.object_from_world.point(wp - 1e-3 * glm::normalize(wn));
            CHECK(glm::length(outside) > 1);
            CHECK(glm::length(inside) < 1);
        }
    }
}

TEST_CASE("a singular composed transform is a located error at the primitive") {
    GraphBuilder b;
    glm::dmat4 flat(1);
    flat[2][2] = 0;  // multmatrix squashing z
    b.next_line = 7;
    const auto leaf = b.sphere(1);  // line 7
    const auto top = b.xform(flat, b.translate({1, 0, 0}, leaf));
    try {
        lower_to_csg(b.finish({top}));
        FAIL("no error");
    } catch (const SourceError& e) {
        CHECK(e.diagnostic().loc.line == 7);
        CHECK(e.diagnostic().loc.file->path == "test.sdl");
        CHECK(std::string(e.what()).find("singular") != std::string::npos);
    }
}

TEST_CASE("rank-deficient shears and non-finite matrices are errors too") {
    {
        GraphBuilder b;
        glm::dmat4 m(1);
        m[0] = {1, 2, 3, 0};
        m[1] = {2, 4, 6, 0};  // parallel columns
        CHECK_THROWS_AS(lower_to_csg(b.finish({b.xform(m, b.cube(1))})), SourceError);
    }
    {
        GraphBuilder b;
        glm::dmat4 m(1);
        m[3][0] = std::numeric_limits<double>::infinity();
        CHECK_THROWS_AS(lower_to_csg(b.finish({b.xform(m, b.cube(1))})), SourceError);
    }
    {  // two tiny (but individually fine) scales: still a regular transform
        GraphBuilder b;
        const auto top = b.scale(glm::dvec3(1e-60), b.scale(glm::dvec3(1e-60), b.sphere(1)));
        graph::SceneGraph& g = b.finish({top});
        // Far below what the default camera frames (1e-30): a camera of its own.
        g.camera = csg::Camera{};
        const csg::Scene s = lower_to_csg(g);
        CHECK(s.leaves[0].bounds.hi.x == Approx(1e-120));
    }
}
