// The stdlib's solids lowered and judged by the point-membership oracle
// (csg/membership.hpp): the shape a module promises, not the nodes it makes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "csg/membership.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;
using kerf::test::lowered;

TEST_CASE("regular_prism is the regular n-gon prism: inside at its corners, outside beyond its flats") {
    for (int n : {3, 5, 6, 8}) {
        for (bool center : {false, true}) {
            const double r = 2, h = 3, apothem = r * std::cos(std::numbers::pi / n);
            const csg::Scene s = lowered("use <shapes.sdl>\nregular_prism(" + std::to_string(n) + ", 2, 3, center = " +
                                         (center ? "true" : "false") + ");");
            const double zmid = center ? 0 : h / 2;
            INFO("n = " << n << ", center = " << center);
            for (int k = 0; k < n; ++k) {
                const double corner = 2 * std::numbers::pi * k / n, flat = corner + std::numbers::pi / n;
                auto at = [&](double angle, double radius, double z) {
                    return glm::dvec3(radius * std::cos(angle), radius * std::sin(angle), z);
                };
                CHECK(csg::contains(s, at(corner, 0.999 * r, zmid)));        // just inside a corner
                CHECK_FALSE(csg::contains(s, at(corner, 1.001 * r, zmid)));  // beyond it
                CHECK(csg::contains(s, at(flat, 0.999 * apothem, zmid)));    // just inside a flat
                // Beyond a flat but inside the circumscribed cylinder: the
                // part the sides cut away.
                CHECK_FALSE(csg::contains(s, at(flat, 1.001 * apothem, zmid)));
                CHECK_FALSE(csg::contains(s, at(flat, 0.5 * (apothem + r), zmid)));
            }
            CHECK(csg::contains(s, {0, 0, zmid}));
            CHECK_FALSE(csg::contains(s, {0, 0, zmid + 0.501 * h}));  // above the top cap
            CHECK_FALSE(csg::contains(s, {0, 0, zmid - 0.501 * h}));  // below the bottom one
        }
    }
}
