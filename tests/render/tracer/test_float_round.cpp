// The tracer hands Embree float bounds rounded outwards
// (render/tracer/float_round.hpp), stepping a float up or down by bit
// arithmetic instead of calling std::nextafter per ray end. The rays' and
// boxes' floats, and so every image, depend on these being exactly
// nextafter's: checked here against it on zeros, denormals, the largest
// floats, infinities and a spread of doubles of every magnitude and sign,
// also with the render threads' flush-to-zero and denormals-are-zero set.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>
#include <xmmintrin.h>
#include <pmmintrin.h>

#include "render/tracer/float_round.hpp"

namespace {

using FL = std::numeric_limits<float>;

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

float reference_down(double x) {
    const float f = float(x);
    return double(f) > x ? std::nextafter(f, -FL::infinity()) : f;
}

float reference_up(double x) {
    const float f = float(x);
    return double(f) < x ? std::nextafter(f, FL::infinity()) : f;
}

std::vector<double> samples() {
    std::vector<double> xs{0.0, -0.0, 1.0, -1.0, double(FL::denorm_min()), -double(FL::denorm_min()),
                           double(FL::min()), -double(FL::min()), double(FL::max()), -double(FL::max()),
                           1e39, -1e39, 1e-46, -1e-46, std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
    // Doubles between floats and on them, at every magnitude.
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> mant(0.5, 1.0);
    std::uniform_int_distribution<int> expo(-160, 130), sign(0, 1);
    for (int i = 0; i < 20000; ++i) {
        const double x = std::ldexp(mant(g), expo(g)) * (sign(g) ? -1 : 1);
        xs.push_back(x);
        xs.push_back(double(float(x)));
    }
    return xs;
}

void check_all() {
    for (const double x : samples()) {
        INFO("x = " << x);
        CHECK(same_bits(kerf::render::round_down(x), reference_down(x)));
        CHECK(same_bits(kerf::render::round_up(x), reference_up(x)));
    }
}

}  // namespace

TEST_CASE("float rounding outwards matches nextafter bit for bit", "[render][tracer]") {
    check_all();
}

TEST_CASE("float rounding outwards matches nextafter under flush-to-zero", "[render][tracer]") {
    const unsigned int csr = _mm_getcsr();
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    check_all();
    _mm_setcsr(csr);
}
