// Embree's rays and boxes are float while every decision of the tracer is
// made in double. Bounds handed to Embree are rounded outwards (lower ends
// down, upper ends up) so that its float culling never drops what the double
// arithmetic would keep.
#pragma once
#include <cmath>
#include <limits>

namespace kerf::render {

inline float round_down(double x) {
    float f = float(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

inline float round_up(double x) {
    float f = float(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace kerf::render
