// The sRGB transfer functions against their IEC 61966-2-1 definition.
#include <catch2/catch.hpp>

#include <cmath>

#include "csg/srgb.hpp"

using namespace kerf::csg;

TEST_CASE("sRGB transfer functions", "[colors]") {
    CHECK(srgb_to_linear(0.0) == 0);
    CHECK(srgb_to_linear(1.0) == Approx(1).epsilon(1e-15));
    CHECK(srgb_to_linear(0.04) == Approx(0.04 / 12.92));              // linear toe
    CHECK(srgb_to_linear(0.5) == Approx(std::pow(0.555 / 1.055, 2.4)));  // 0.21404
    CHECK(srgb_to_linear(0.5) == Approx(0.214041).epsilon(1e-5));
    for (double c = 0; c <= 1.0; c += 0.01) CHECK(linear_to_srgb(srgb_to_linear(c)) == Approx(c).margin(1e-12));
    glm::dvec3 v = srgb_to_linear(glm::dvec3(1, 0.5, 0));
    CHECK(v.x == Approx(1));
    CHECK(v.y == Approx(0.214041).epsilon(1e-5));
    CHECK(v.z == 0);
}
