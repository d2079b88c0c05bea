#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("paraboloid: random rays against the oracle, all scales", "[prim][paraboloid][accuracy]") {
    random_suite("paraboloid", [](double s) { return make_leaf(PrimKind::Paraboloid, {s, 0.7 * s}); }, 8, 8, 16000,
                 4000, 601);
    random_suite("paraboloid-narrow", [](double s) { return make_leaf(PrimKind::Paraboloid, {s, 0.05 * s}); }, 8, 8,
                 6000, 2000, 602);
}

TEMPLATE_TEST_CASE("paraboloid: closed-form crossings", "[prim][paraboloid]", float, double) {
    const double eps = std::numeric_limits<TestType>::epsilon();
    for (double s : {1e-6, 1.0, 1e6}) {
        const double h = 2 * s, r = s;  // z > 2ρ²/s
        const auto leaf = make_leaf(PrimKind::Paraboloid, {h, r});
        const double tol = 16 * eps * s;
        INFO("scale " << s);
        // Up the axis: apex to cap (the linear case).
        CHECK(compare_spans<TestType>(leaf, {0, 0, -s}, {0, 0, 1}, {{s, 3 * s}}, tol) == "");
        CHECK(compare_spans<TestType>(leaf, {0, 0, 3 * s}, {0, 0, -2}, {{0.5 * s, 1.5 * s}}, tol) == "");
        // Across at z = s/2: ρ < s/2.
        CHECK(compare_spans<TestType>(leaf, {-2 * s, 0, s / 2}, {1, 0, 0}, {{1.5 * s, 2.5 * s}}, tol) == "");
        // In the cap plane: outside.
        CHECK(compare_spans<TestType>(leaf, {-2 * s, 0, h}, {1, 0, 0}, {}, 0) == "");
        // Grazing the apex from above / below (double: down to 1e-9).
        for (double delta : {1e-3, 1e-6, 1e-9}) {
            if (sizeof(TestType) == 4 && delta < 1e-6) continue;
            const double z = delta * s, w = std::sqrt(z * s / 2);
            CHECK(compare_spans<TestType>(leaf, {-2 * s, 0, z}, {1, 0, 0}, {{2 * s - w, 2 * s + w}},
                                          16 * eps * s * s / w) == "");
            CHECK(compare_spans<TestType>(leaf, {-2 * s, 0, -z}, {1, 0, 0}, {}, 0) == "");
        }
    }
}
