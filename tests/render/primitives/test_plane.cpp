#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

namespace {
Leaf plane(double offset) {
    const dvec3 n = glm::normalize(dvec3(0.3, -0.5, 0.8));
    return make_leaf(PrimKind::Plane, {n.x, n.y, n.z, offset});
}
}  // namespace

TEST_CASE("plane: random rays against the membership oracle, all scales", "[prim][plane][accuracy]") {
    random_suite("plane", [](double s) { return plane(0.2 * s); }, 8, 8, 20000, 4000, 301);
    random_suite("plane+1e6", [](double s) { return plane(1e6 + 0.2 * s); }, 8, 8, 2000, 1000, 302);
}

TEMPLATE_TEST_CASE("plane: half-space spans", "[prim][plane]", float, double) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto ground = make_leaf(PrimKind::Plane, {0, 0, 1, 2});  // z < 2
    CHECK(compare_spans<TestType>(ground, {0, 0, 5}, {0, 0, -1}, {{3, inf}}, 0) == "");
    CHECK(compare_spans<TestType>(ground, {0, 0, 5}, {0, 0, 2}, {{-inf, -1.5}}, 0) == "");
    // Parallel: inside is the whole line, outside or on the boundary nothing.
    CHECK(compare_spans<TestType>(ground, {0, 0, 1}, {1, 0, 0}, {{-inf, inf}}, 0) == "");
    CHECK(compare_spans<TestType>(ground, {0, 0, 2}, {1, 0, 0}, {}, 0) == "");
    CHECK(compare_spans<TestType>(ground, {0, 0, 3}, {1, 1, 0}, {}, 0) == "");
    // Starting on the boundary.
    CHECK(compare_spans<TestType>(ground, {7, -3, 2}, {0, 1, -4}, {{0, inf}}, 0) == "");
}

TEST_CASE("plane: nearly parallel rays cross where the closed form says", "[prim][plane]") {
    const auto ground = make_leaf(PrimKind::Plane, {0, 0, 1, 0});
    for (double slope : {1e-3, 1e-6, 1e-9}) {
        // From z = 1 descending by `slope` per unit: crosses at t = 1/slope.
        constexpr double inf = std::numeric_limits<double>::infinity();
        CHECK(compare_spans<double>(ground, {0, 0, 1}, {1, 0, -slope}, {{1 / slope, inf}}, 1e-15 / slope) == "");
        const double sf = float(slope);
        CHECK(compare_spans<float>(ground, {0, 0, 1}, {1, 0, -slope}, {{1 / sf, inf}}, 1e-6 / sf) == "");
    }
}
