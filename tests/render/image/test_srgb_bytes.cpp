// The 8-bit sRGB code (srgb_bytes.hpp) against its definition, by another
// route than the table: round(255 · encode(v)) for v in (0, 1), where
// encode is csg/srgb.hpp's curve in double, and, where a value sits within
// round-off of a half code (so rounding the curve could go either way),
// the count of thresholds at or below it. Every float near a threshold or a
// bin's edge is checked, and a stride through all of (0, 1); the exhaustive
// run over all 2^32 float patterns is in docs/performance.md.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "csg/srgb.hpp"
#include "render/image/srgb_bytes.hpp"

using namespace kerf::render;

namespace {

float from_bits(std::uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

// The code by the definition: thresholds are where (k - 0.5) / 255 is
// reached, so this is round(255 · encode(v)) but for ties within the
// float thresholds' own round-off, which the threshold count decides.
int expected(const SrgbTable& table, float v) {
    if (!(v > 0)) return 0;
    if (v >= 1) return 255;
    const double e = 255 * kerf::csg::linear_to_srgb(double(v));
    const double frac = e - std::floor(e);
    if (std::abs(frac - 0.5) > 1e-3) return int(std::lround(e));
    int count = 0;
    while (count < 255 && v >= table.threshold[count]) ++count;
    return count;
}

void check_around(const SrgbTable& table, float v, int ulps) {
    std::uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    for (int d = -ulps; d <= ulps; ++d) {
        const float f = from_bits(std::uint32_t(std::int64_t(b) + d));
        if (!(f > 0 && f < 1)) continue;
        INFO("v = " << f);
        REQUIRE(int(srgb_byte(table, f)) == expected(table, f));
    }
}

}  // namespace

TEST_CASE("srgb_byte: every float near a threshold or a bin edge gets its code by the curve", "[render][srgb]") {
    const SrgbTable& table = srgb_table();
    for (int k = 0; k < 255; ++k) check_around(table, table.threshold[k], 64);
    for (int b = 0; b <= SrgbTable::kBins; ++b)
        check_around(table, from_bits(SrgbTable::kLowBits + (std::uint32_t(b) << SrgbTable::kShift)), 64);
    check_around(table, SrgbTable::kLow, 4096);
}

TEST_CASE("srgb_byte: a stride through (0, 1) gets the code by the curve", "[render][srgb]") {
    const SrgbTable& table = srgb_table();
    const std::uint32_t one = 0x3F800000u;
    for (std::uint32_t b = 1; b < one; b += 9973) {
        const float f = from_bits(b);
        INFO("v = " << f);
        REQUIRE(int(srgb_byte(table, f)) == expected(table, f));
    }
}

TEST_CASE("srgb_byte: zero, negatives, NaN give 0, one and above 255", "[render][srgb]") {
    const SrgbTable& table = srgb_table();
    CHECK(srgb_byte(table, 0.0f) == 0);
    CHECK(srgb_byte(table, -0.0f) == 0);
    CHECK(srgb_byte(table, -0.5f) == 0);
    CHECK(srgb_byte(table, -std::numeric_limits<float>::infinity()) == 0);
    CHECK(srgb_byte(table, std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(srgb_byte(table, std::numeric_limits<float>::denorm_min()) == 0);
    CHECK(srgb_byte(table, 1.0f) == 255);
    CHECK(srgb_byte(table, 7.5f) == 255);
    CHECK(srgb_byte(table, std::numeric_limits<float>::infinity()) == 255);
    CHECK(srgb_byte(table, std::nextafter(1.0f, 0.0f)) == 255);
    CHECK(srgb_byte(table, 0.5f) == 188);  // 255 · (1.055 · 0.5^(1/2.4) − 0.055) = 187.5...
}
