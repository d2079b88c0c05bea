#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("cylinder, frustum, cones: random rays against the oracle, all scales", "[prim][cylinder][accuracy]") {
    random_suite("cylinder", [](double s) { return make_leaf(PrimKind::Cylinder, {-0.5 * s, 0.7 * s, 0.6 * s, 0.6 * s}); },
                 8, 8, 12000, 3000, 401);
    random_suite("frustum", [](double s) { return make_leaf(PrimKind::Cylinder, {-0.5 * s, 0.7 * s, 0.6 * s, 0.3 * s}); },
                 8, 8, 12000, 3000, 402);
    random_suite("cone", [](double s) { return make_leaf(PrimKind::Cylinder, {0, s, 0.5 * s, 0}); }, 8, 8, 12000, 3000,
                 403);
    random_suite("cone-down", [](double s) { return make_leaf(PrimKind::Cylinder, {0, s, 0, 0.5 * s}); }, 8, 8, 8000,
                 2000, 404);
    random_suite("cylinder z+1e6", [](double s) { return make_leaf(PrimKind::Cylinder, {1e6, 1e6 + s, s, s}); }, 8, 8,
                 2000, 1000, 405);
}

TEMPLATE_TEST_CASE("cylinder: closed-form crossings", "[prim][cylinder]", float, double) {
    const double eps = std::numeric_limits<TestType>::epsilon();
    for (double s : {1e-6, 1.0, 1e6}) {
        const auto cyl = make_leaf(PrimKind::Cylinder, {0, 2 * s, s, s});
        const double tol = 16 * eps * s;
        INFO("scale " << s);
        // Along the axis: cap to cap; starting inside.
        CHECK(compare_spans<TestType>(cyl, {0, 0, -s}, {0, 0, 1}, {{s, 3 * s}}, tol) == "");
        CHECK(compare_spans<TestType>(cyl, {0, 0, s}, {0, 0, -4}, {{-s / 4, s / 4}}, tol) == "");
        // Across the side at mid height, through the axis.
        CHECK(compare_spans<TestType>(cyl, {-3 * s, 0, s}, {2, 0, 0}, {{s, 2 * s}}, tol) == "");
        // Lying in a cap plane, or along the side line: outside (degenerate rule).
        CHECK(compare_spans<TestType>(cyl, {-3 * s, 0, 2 * s}, {1, 0, 0}, {}, 0) == "");
        CHECK(compare_spans<TestType>(cyl, {s, 0, -s}, {0, 0, 1}, {}, 0) == "");
        // Through the rim (edge) diagonally: enters at the rim on the cap.
        const auto sp = compare_spans<TestType>(cyl, {-2 * s, 0, 3 * s}, {1, 0, -1}, {{s, 3 * s}}, tol);
        CHECK(sp == "");
        // A cone along its axis through the apex: from the base to the apex.
        const auto cone = make_leaf(PrimKind::Cylinder, {0, s, s, 0});
        CHECK(compare_spans<TestType>(cone, {0, 0, -s}, {0, 0, 1}, {{s, 2 * s}}, tol) == "");
        // The cone at half height has radius s/2.
        CHECK(compare_spans<TestType>(cone, {-s, 0, s / 2}, {1, 0, 0}, {{s / 2, 1.5 * s}}, tol) == "");
    }
}

TEST_CASE("cylinder: rays grazing the side down to 1e-9", "[prim][cylinder]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        const auto cyl = make_leaf(PrimKind::Cylinder, {0, 2 * s, s, s});
        for (double delta : {1e-3, 1e-6, 1e-9}) {
            const double y = s * (1 - delta), half = std::sqrt((s - y) * (s + y));
            INFO("scale " << s << " delta " << delta);
            CHECK(compare_spans<double>(cyl, {-5 * s, y, s}, {1, 0, 0}, {{5 * s - half, 5 * s + half}},
                                        8 * 0x1p-52 * s * s / half) == "");
            CHECK(compare_spans<double>(cyl, {-5 * s, s * (1 + delta), s}, {1, 0, 0}, {}, 0) == "");
            // Oblique grazing rays, also past the rims, checked by the oracle.
            CheckStats st, sf;
            RayGen gen(11);
            for (int i = 0; i < 2000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586), z = gen.uniform(-0.5, 2.5) * s;
                const dvec3 radial(std::cos(phi), std::sin(phi), 0), tangent(-std::sin(phi), std::cos(phi), 0);
                const dvec3 dir = glm::normalize(tangent + dvec3(0, 0, gen.uniform(-1, 1)));
                const dvec3 at = radial * s * (1 + (i % 2 ? delta : -delta)) + dvec3(0, 0, z);
                check_ray<double>(cyl, at - 3 * s * dir, dir, 8, s, st);
                check_ray<float>(cyl, at - 3 * s * dir, dir, 8, s, sf);
            }
            INFO(st.first_failure << " / " << sf.first_failure);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
        }
    }
}
