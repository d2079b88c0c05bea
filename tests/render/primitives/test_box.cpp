#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

namespace {
Leaf box(double s, dvec3 shift = dvec3(0)) {
    const dvec3 lo = shift + s * dvec3(-0.3, -0.6, -0.2), hi = shift + s * dvec3(0.7, 0.4, 0.9);
    return make_leaf(PrimKind::Box, {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
}
}  // namespace

TEST_CASE("box: random rays against the membership oracle, all scales", "[prim][box][accuracy]") {
    random_suite("box", [](double s) { return box(s); }, 8, 8, 20000, 4000, 201);
}

TEST_CASE("box: corners 1e6 away from the origin", "[prim][box][accuracy]") {
    // Corner parameters far out: L in the tolerance grows with them.
    random_suite("box+1e6", [](double s) { return box(s, dvec3(1e6, -1e6, 1e6)); }, 8, 8, 4000, 1000, 202);
}

TEMPLATE_TEST_CASE("box: edges, corners, faces and axis rays", "[prim][box]", float, double) {
    const auto unit = make_leaf(PrimKind::Box, {0, 0, 0, 1, 1, 1});
    // Through two opposite corners along the diagonal.
    CHECK(compare_spans<TestType>(unit, {-1, -1, -1}, {1, 1, 1}, {{1, 2}}, 0) == "");
    // Along an axis through the middle, un-normalised.
    CHECK(compare_spans<TestType>(unit, {0.5, 0.5, 4}, {0, 0, -2}, {{1.5, 2}}, 0) == "");
    // A ray lying in a face plane, or along an edge, is outside (degenerate rule).
    CHECK(compare_spans<TestType>(unit, {-1, 0.5, 1}, {1, 0, 0}, {}, 0) == "");
    CHECK(compare_spans<TestType>(unit, {-1, 0, 0}, {1, 0, 0}, {}, 0) == "");
    CHECK(compare_spans<TestType>(unit, {-1, 1, 1}, {1, 0, 0}, {}, 0) == "");
    // A ray crossing the cube's face plane at a corner (tangent at a point): no span.
    CHECK(compare_spans<TestType>(unit, {-1, 0, 1}, {1, 1, -1}, {}, 0) == "");
    // Through an edge into the solid: the span starts on the edge.
    CHECK(compare_spans<TestType>(unit, {-1, 0.5, -1}, {1, 0, 1}, {{1, 2}}, 0) == "");
    // Starting exactly on a face.
    CHECK(compare_spans<TestType>(unit, {0.5, 0.5, 1}, {0, 0, -1}, {{0, 1}}, 0) == "");
    // Grazing a face at 1e-9 (double) / 1e-6 (float) inside and outside.
    const double g = sizeof(TestType) == 8 ? 1e-9 : 1e-6;
    CHECK(compare_spans<TestType>(unit, {-1, 0.5, 1 - g}, {1, 0, 0}, {{1, 2}}, 0) == "");
    CHECK(compare_spans<TestType>(unit, {-1, 0.5, 1 + g}, {1, 0, 0}, {}, 0) == "");
}

TEMPLATE_TEST_CASE("box: flush neighbours and identical boxes agree bit for bit", "[prim][box]", float, double) {
    const auto a = make_leaf(PrimKind::Box, {0, 0, 0, 1, 1, 1});
    const auto b = make_leaf(PrimKind::Box, {1, 0, 0, 2, 1, 1});
    RayGen gen(5);
    int shared = 0;
    for (int i = 0; i < 20000; ++i) {
        const dvec3 o = dvec3(-1, 0, 0) + dvec3(gen.uniform(0, 0.2), gen.uniform(0, 1), gen.uniform(0, 1));
        const dvec3 d = dvec3(1, gen.uniform(-0.2, 0.2), gen.uniform(-0.2, 0.2)) * gen.uniform(0.1, 10);
        using V = glm::vec<3, TestType>;
        kerf::csg::Span<TestType> sa[2], sb[2], sa2[2];
        const int na = kerf::csg::intersect_leaf<TestType>(a, V(o), V(d), sa);
        const int nb = kerf::csg::intersect_leaf<TestType>(b, V(o), V(d), sb);
        REQUIRE(kerf::csg::intersect_leaf<TestType>(a, V(o), V(d), sa2) == na);
        if (na == 1) REQUIRE((sa2[0].t0 == sa[0].t0 && sa2[0].t1 == sa[0].t1));
        if (na == 1 && nb == 1 && sa[0].part1 == 3) {
            REQUIRE(sb[0].part0 == 0);
            REQUIRE(sa[0].t1 == sb[0].t0);  // the shared face x = 1: no gap, no overlap
            ++shared;
        }
    }
    CHECK(shared > 1000);
}
