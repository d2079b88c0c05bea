#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("sphere: random rays against the membership oracle, all scales", "[prim][sphere][accuracy]") {
    random_suite("sphere", [](double s) { return make_leaf(PrimKind::Sphere, {s}); }, 8, 8, 20000, 4000, 101);
}

TEMPLATE_TEST_CASE("sphere: closed-form crossings", "[prim][sphere]", float, double) {
    const double eps = std::numeric_limits<TestType>::epsilon();
    for (double s : {1e-6, 1.0, 1e6}) {
        const auto leaf = make_leaf(PrimKind::Sphere, {s});
        // Through both poles along the axis, with an un-normalised direction.
        CHECK(compare_spans<TestType>(leaf, {0, 0, -5 * s}, {0, 0, 2}, {{2 * s, 3 * s}}, 16 * eps * s) == "");
        // Starting exactly on the surface, inward and outward.
        CHECK(compare_spans<TestType>(leaf, {s, 0, 0}, {-1, 0, 0}, {{0, 2 * s}}, 16 * eps * s) == "");
        CHECK(compare_spans<TestType>(leaf, {s, 0, 0}, {1, 0, 0}, {{-2 * s, 0}}, 16 * eps * s) == "");
        // Starting at the centre: the span covers t < 0 too (whole line).
        CHECK(compare_spans<TestType>(leaf, {0, 0, 0}, {0, 3, 0}, {{-s / 3, s / 3}}, 16 * eps * s) == "");
    }
}

TEST_CASE("sphere: rays grazing the silhouette down to 1e-9", "[prim][sphere]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        const auto leaf = make_leaf(PrimKind::Sphere, {s});
        for (double delta : {1e-3, 1e-6, 1e-9}) {
            const double y_in = s * (1 - delta), y_out = s * (1 + delta);
            const double half = std::sqrt((s - y_in) * (s + y_in));
            // Near a graze the chord's ends move fast with the offset: an error
            // of eps·s in the closest point moves them by eps·s²/half.
            const double tol_d = 8 * 0x1p-52 * s * s / half, tol_f = 8 * 0x1p-23 * s * s / half;
            INFO("scale " << s << " delta " << delta);
            CHECK(compare_spans<double>(leaf, {-5 * s, y_in, 0}, {1, 0, 0}, {{5 * s - half, 5 * s + half}},
                                        tol_d) == "");
            CHECK(compare_spans<double>(leaf, {-5 * s, y_out, 0}, {1, 0, 0}, {}, 0) == "");
            if (delta >= 1e-6) {  // float resolves 1e-6 (~16 ulps) but not 1e-9
                // The truth for the float solve is the ray and radius rounded to float.
                const double yf = float(y_in), sf = float(s), xf = float(-5 * s);
                const double halff = std::sqrt((sf - yf) * (sf + yf));
                CHECK(compare_spans<float>(leaf, {-5 * s, y_in, 0}, {1, 0, 0}, {{-xf - halff, -xf + halff}},
                                           tol_f) == "");
                CHECK(compare_spans<float>(leaf, {-5 * s, y_out, 0}, {1, 0, 0}, {}, 0) == "");
            }
            // Oblique grazing rays in every direction, checked by the oracle.
            CheckStats st, sf;
            RayGen gen(7);
            for (int i = 0; i < 2000; ++i) {
                const dvec3 u = gen.unit(), v = glm::normalize(glm::cross(u, gen.unit()));
                const double off = s * (1 + (i % 2 ? delta : -delta));
                check_ray<double>(leaf, off * v - 3 * s * u, u, 8, s, st);
                check_ray<float>(leaf, off * v - 3 * s * u, u, 8, s, sf);
            }
            INFO(st.first_failure << " / " << sf.first_failure);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
            CHECK(st.hits == 1000);  // double: exactly the inner half hit
        }
    }
}
