// Embree's rays and boxes are float while every decision of the tracer is
// made in double. Bounds handed to Embree are rounded outwards (lower ends
// down, upper ends up) so that its float culling never drops what the double
// arithmetic would keep.
#pragma once
#include <bit>
#include <cstdint>

namespace kerf::render {

// The next float above f, as std::nextafter(f, +inf) gives it, for an f
// below +inf and not NaN (the callers' comparisons exclude both): inline
// bit steps instead of a libm call per ray end (~1 % of a crowd's time).
// Zero of either sign steps to the smallest denormal, -inf to -FLT_MAX.
// On the bits alone, as libm does: the render threads treat denormals as
// zero (DAZ), which would fool a floating-point test.
inline float next_float_up(float f) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
    if ((bits & 0x7fffffffu) == 0) return std::bit_cast<float>(std::uint32_t(1));
    return std::bit_cast<float>(bits >> 31 ? bits - 1 : bits + 1);
}

inline float round_down(double x) {
    float f = float(x);
    return double(f) > x ? -next_float_up(-f) : f;
}

inline float round_up(double x) {
    float f = float(x);
    return double(f) < x ? next_float_up(f) : f;
}

}  // namespace kerf::render
