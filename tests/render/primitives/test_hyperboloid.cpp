#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("hyperboloid: random rays against the oracle, all scales", "[prim][hyperboloid][accuracy]") {
    random_suite("hyperboloid", [](double s) { return make_leaf(PrimKind::Hyperboloid, {s, 0.6 * s, 0.3 * s}); }, 8,
                 8, 16000, 4000, 701);
    random_suite("hyperboloid-barrel", [](double s) { return make_leaf(PrimKind::Hyperboloid, {s, 0.3 * s, 0.6 * s}); },
                 8, 8, 6000, 2000, 702);
    random_suite("double-cone", [](double s) { return make_leaf(PrimKind::Hyperboloid, {s, 0.6 * s, 0}); }, 8, 8, 6000,
                 2000, 703);
}

TEMPLATE_TEST_CASE("hyperboloid: closed-form crossings", "[prim][hyperboloid]", float, double) {
    const double eps = std::numeric_limits<TestType>::epsilon();
    for (double s : {1e-6, 1.0, 1e6}) {
        const double h = 2 * s, r = 2 * s, w = s;  // ρ² < s² + 3z²
        const auto leaf = make_leaf(PrimKind::Hyperboloid, {h, r, w});
        const double tol = 16 * eps * s;
        INFO("scale " << s);
        CHECK(compare_spans<TestType>(leaf, {0, 0, -2 * s}, {0, 0, 1}, {{s, 3 * s}}, tol) == "");
        CHECK(compare_spans<TestType>(leaf, {-3 * s, 0, 0}, {1, 0, 0}, {{2 * s, 4 * s}}, tol) == "");
        // Along x at y = s, z = s/2 (cross-section radius² = 1.75s²): inside where x² < 0.75s².
        const double a = std::sqrt(0.75) * s;
        CHECK(compare_spans<TestType>(leaf, {-3 * s, s, 0.5 * s}, {1, 0, 0}, {{3 * s - a, 3 * s + a}}, tol) == "");
        // Nearly parallel to the axis just outside the waist: enters/leaves through the flaring side
        // twice: x = 1.2s, y = 0, the side is at z² = (1.44 - 1)/3 s².
        const double zs = std::sqrt(0.44 / 3) * s;
        CHECK(compare_spans<TestType>(leaf, {1.2 * s, 0, -2 * s}, {0, 0, 1}, {{s, 2 * s - zs}, {2 * s + zs, 3 * s}},
                                      tol) == "");
        // Grazing the waist circle from inside and outside.
        for (double delta : {1e-3, 1e-6, 1e-9}) {
            if (sizeof(TestType) == 4 && delta < 1e-6) continue;
            const double y = w * (1 - delta), half = std::sqrt((w - y) * (w + y));
            CHECK(compare_spans<TestType>(leaf, {-3 * s, y, 0}, {1, 0, 0}, {{3 * s - half, 3 * s + half}},
                                          16 * eps * s * s / half) == "");
        }
    }
}

TEST_CASE("hyperboloid: rays along the surface's own straight rulings", "[prim][hyperboloid]") {
    // ρ² = w² + κz² contains the lines (w cosθ, w sinθ, 0) + s(-sinθ, cosθ, 1/√κ)·w.
    // A ray lying in the surface is outside (up to the tolerance band).
    const double w = 1, r = 2, h = 2, kappa = (r * r - w * w) / 1.0;
    const auto leaf = make_leaf(PrimKind::Hyperboloid, {h, r, w});
    CheckStats st, sf;
    for (int i = 0; i < 360; ++i) {
        const double th = i * 0.017453292519943295;
        const dvec3 p(w * std::cos(th), w * std::sin(th), 0), dir(-std::sin(th), std::cos(th), 1 / std::sqrt(kappa));
        check_ray<double>(leaf, p - 2.0 * dir, dir, 8, 1, st);
        check_ray<float>(leaf, p - 2.0 * dir, dir, 8, 1, sf);
    }
    INFO(st.first_failure << " / " << sf.first_failure);
    CHECK(st.failures == 0);
    CHECK(sf.failures == 0);
}
