// Lowering's short ways for translated leaves (lower/leaf_placement.cpp,
// lower/flat_tree.cpp: docs/performance.md, "The front end, again") must
// give the bits of the general path: the tracer's answers, and so the
// images, depend on every bit of a leaf's matrices and box. The expected
// values here are the general formulas, written out.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "lower/leaf_placement.hpp"
#include "lower/lower.hpp"
#include "lower/primitive_bounds.hpp"
#include "tests/lower/graph_builder.hpp"

using namespace kerf;

namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// What the general path makes of a sphere under wfo.
csg::Leaf general_sphere(double r, const csg::Affine& wfo) {
    csg::Leaf leaf;
    leaf.kind = csg::PrimKind::Sphere;
    leaf.p[0] = r;
    leaf.world_from_object = wfo;
    leaf.object_from_world = invert(wfo);
    leaf.bounds = primitive_bounds(csg::PrimKind::Sphere, leaf.p, wfo);
    return leaf;
}

void check_translated_sphere(double r, const glm::dvec3& offset) {
    csg::Affine wfo;
    wfo.offset = offset;
    csg::Leaf leaf;
    leaf.kind = csg::PrimKind::Sphere;
    leaf.p[0] = r;
    place_leaf(leaf, wfo, nullptr, SourceLoc{});
    const csg::Leaf want = general_sphere(r, wfo);
    INFO("r = " << r << ", offset = " << offset.x << ", " << offset.y << ", " << offset.z);
    CHECK(same_bits(leaf.world_from_object, want.world_from_object));
    CHECK(same_bits(leaf.object_from_world.linear, want.object_from_world.linear));
    CHECK(same_bits(leaf.object_from_world.offset, want.object_from_world.offset));
    CHECK(same_bits(leaf.bounds, want.bounds));
}

}  // namespace

TEST_CASE("a translated sphere is placed with the general path's bits") {
    const double z = 0.0, nz = -0.0;
    // Signed zeros: the inverse's offset is -(I·o), whose zero signs are not -o's.
    for (const glm::dvec3 o : {glm::dvec3(z, z, z), glm::dvec3(nz, nz, nz), glm::dvec3(nz, 1, z), glm::dvec3(1, nz, -2),
                               glm::dvec3(1e-300, -1e-310, 5e-324), glm::dvec3(-1e7, 3e8, 0.1)})
        for (double r : {1e-9, 0.07, 1.0, 123.456}) check_translated_sphere(r, o);
    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> exponent(-12, 8), unit(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        const auto any = [&] { return unit(rng) * std::pow(10.0, exponent(rng)); };
        check_translated_sphere(std::abs(any()), glm::dvec3(any(), any(), any()));
    }
}

TEST_CASE("a translated sphere's errors are the general path's") {
    csg::Leaf leaf;
    leaf.kind = csg::PrimKind::Sphere;
    leaf.p[0] = 1;
    csg::Affine far;
    far.offset = glm::dvec3(0, 2 * csg::kRenderableRange, 0);
    CHECK_THROWS_WITH(place_leaf(leaf, far, nullptr, SourceLoc{}), Catch::Contains("kerf renders solids within"));
    csg::Affine nan;
    nan.offset = glm::dvec3(0, std::numeric_limits<double>::quiet_NaN(), 0);
    CHECK_THROWS_WITH(place_leaf(leaf, nan, nullptr, SourceLoc{}), Catch::Contains("not finite"));
}

// A translation under another transform: the frame's linear part times the
// identity is that part bit for bit only when it holds no -0 (a product
// with 0 and a sum with +0 turn it into +0) and no infinity. Under such a
// frame lowering must still compose in full.
TEST_CASE("lowering composes a translation under any frame with compose's bits") {
    const double nz = -0.0;
    // A mirror with -0 off the diagonal that survives the root frame's
    // product (its column's other products are -0 too), and which the next
    // product with the identity turns into +0.
    glm::dmat4 signed_zero(1.0);
    signed_zero[0][0] = -1;
    signed_zero[1] = glm::dvec4(nz, -1, nz, 0);
    signed_zero[3] = glm::dvec4(0.5, nz, 2, 1);
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1), glm::radians(30.0), glm::dvec3(1, 2, 3));
    const glm::dmat4 skew = glm::dmat4(glm::dvec4(2, 0.5, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(-0.25, 0, 3, 0),
                                       glm::dvec4(nz, 1, -1, 1));
    for (const glm::dmat4& outer : {glm::dmat4(1.0), signed_zero, turn, skew}) {
        test::GraphBuilder b;
        const glm::dvec3 t0(nz, 1.5, -2), t1(3, nz, nz);
        b.finish({b.xform(outer, b.uni({b.translate(t0, b.sphere(0.5)), b.translate(t1, b.translate(t0, b.sphere(0.25)))}))});
        const csg::Scene s = lower_to_csg(b.g);
        REQUIRE(s.leaves.size() == 2);
        // compose() of flat_tree.cpp, written out: {P.linear · L, P.linear · t + P.offset}.
        const auto compose = [](const csg::Affine& p, const glm::dmat4& m) {
            return csg::Affine{p.linear * glm::dmat3(m), p.linear * glm::dvec3(m[3]) + p.offset};
        };
        const csg::Affine o = compose(csg::Affine{}, outer);
        const csg::Affine want[2] = {compose(o, glm::translate(glm::dmat4(1), t0)),
                                     compose(compose(o, glm::translate(glm::dmat4(1), t1)), glm::translate(glm::dmat4(1), t0))};
        for (int i = 0; i < 2; ++i) {
            const csg::Leaf& leaf = s.leaves[i];
            CHECK(same_bits(leaf.world_from_object.linear, want[i].linear));
            CHECK(same_bits(leaf.world_from_object.offset, want[i].offset));
            const csg::Leaf general = general_sphere(leaf.p[0], want[i]);
            CHECK(same_bits(leaf.object_from_world.linear, general.object_from_world.linear));
            CHECK(same_bits(leaf.object_from_world.offset, general.object_from_world.offset));
            CHECK(same_bits(leaf.bounds, general.bounds));
        }
    }
}
