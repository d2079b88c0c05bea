// Pattern values against their closed forms (docs/language.md, "Patterns"):
// which checker cell is which, the stripes' period, the gradient's ramp, and
// the noise patterns' range and determinism (a pure function of the point).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#include "render/patterns.hpp"

using namespace kerf;
using csg::Pattern;
using render::pattern_value;

TEST_CASE("checker: (floor x + floor y + floor z) mod 2, the cell of (0.5, 0.5, 0.5) is 0", "[render][patterns]") {
    CHECK(pattern_value(Pattern::Checker, {0.5, 0.5, 0.5}) == 0);
    CHECK(pattern_value(Pattern::Checker, {1.5, 0.5, 0.5}) == 1);
    CHECK(pattern_value(Pattern::Checker, {1.5, 1.5, 0.5}) == 0);
    CHECK(pattern_value(Pattern::Checker, {-0.5, 0.5, 0.5}) == 1);  // floor(-0.5) = -1: odd
    CHECK(pattern_value(Pattern::Checker, {-0.5, -0.5, 0.5}) == 0);
    CHECK(pattern_value(Pattern::Checker, {2.25, -3.75, 7.5}) == 1);  // 2 − 4 + 7 = 5: odd
    for (double x = -5.25; x < 5; x += 0.5)
        for (double y = -5.25; y < 5; y += 0.5)
            for (double z : {-2.5, 0.3, 3.7}) {
                const long cells = long(std::floor(x)) + long(std::floor(y)) + long(std::floor(z));
                INFO(x << " " << y << " " << z);
                CHECK(pattern_value(Pattern::Checker, {x, y, z}) == double(((cells % 2) + 2) % 2));
            }
    // A face on a cell boundary falls in one cell, the one above it.
    CHECK(pattern_value(Pattern::Checker, {0.5, 0.5, -1e-12}) == 0);
    CHECK(pattern_value(Pattern::Checker, {0.5, 0.5, 1e-12}) == 0);
    // Far out the cells are still exact.
    CHECK(pattern_value(Pattern::Checker, {1e15 + 0.5, 0.5, 0.5}) == 0);
    CHECK(pattern_value(Pattern::Checker, {1e15 + 1.5, 0.5, 0.5}) == 1);
}

TEST_CASE("stripes: slabs one unit thick across x, period 2", "[render][patterns]") {
    for (double x = -10.3; x < 10; x += 0.37) {
        INFO(x);
        const double v = pattern_value(Pattern::Stripes, {x, 3.3, -7.1});
        CHECK(v == ((long(std::floor(x)) % 2 + 2) % 2));
        CHECK(pattern_value(Pattern::Stripes, {x + 2, -1, 5}) == v);  // the period, and y, z do not matter
        CHECK(pattern_value(Pattern::Stripes, {x + 1, 0, 0}) == 1 - v);
    }
}

TEST_CASE("gradient: the fractional part of x, a ramp from 0 to 1 per unit", "[render][patterns]") {
    CHECK(pattern_value(Pattern::Gradient, {0.25, 0, 0}) == 0.25);
    CHECK(pattern_value(Pattern::Gradient, {3.75, 9, -4}) == 0.75);
    CHECK(pattern_value(Pattern::Gradient, {-0.25, 0, 0}) == 0.75);
    CHECK(pattern_value(Pattern::Gradient, {2, 0, 0}) == 0);
}

TEST_CASE("noise, marble, wood: in [0, 1], varied, continuous, a pure function of the point", "[render][patterns]") {
    for (Pattern p : {Pattern::Noise, Pattern::Marble, Pattern::Wood}) {
        double lo = 1, hi = 0, jump = 0;
        std::vector<double> first;
        for (int i = 0; i < 20000; ++i) {
            const glm::dvec3 q(0.0137 * i - 50, 0.71 * std::sin(0.01 * i) * 30, 0.0071 * i);
            const double v = pattern_value(p, q);
            REQUIRE(v >= 0);
            REQUIRE(v <= 1);
            lo = std::min(lo, v), hi = std::max(hi, v);
            first.push_back(v);
            if (p == Pattern::Noise) jump = std::max(jump, std::abs(pattern_value(p, q + glm::dvec3(1e-7)) - v));
        }
        CHECK(hi - lo > 0.5);  // not a constant
        CHECK(jump < 1e-4);    // noise is continuous: a tiny step, a tiny change
        // Computed again on another thread: the same values, bit for bit.
        std::vector<double> again(first.size());
        std::thread t([&] {
            for (int i = 0; i < 20000; ++i)
                again[i] = pattern_value(p, glm::dvec3(0.0137 * i - 50, 0.71 * std::sin(0.01 * i) * 30, 0.0071 * i));
        });
        t.join();
        CHECK(again == first);
    }
    // The lattice noise is its lattice values at integer points and stays in range far out.
    for (double big : {1e9, 1e12, -1e15}) {
        const double v = render::lattice_noise({big + 0.5, big, 0.25});
        CHECK(v >= 0);
        CHECK(v <= 1);
    }
}
