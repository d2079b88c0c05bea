// Sine and cosine of an angle in degrees, as OpenSCAD computes them: the
// angle is folded into [0°, 90°] first, so the angles people type (0, 30,
// 45, 60, 90 and every multiple) give exact values and sin(180) is 0, not
// 1.2e-16. One definition for both rotate() and the sin()/cos() built-ins,
// so a multmatrix written with sin() is the same solid as rotate().
#pragma once
#include <cmath>
#include <limits>
#include <numbers>

namespace kerf {

inline double sin_deg(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    x = std::fmod(x, 360.0);
    if (x < 0) x += 360.0;
    bool negative = false;
    if (x >= 180.0) {
        x -= 180.0;
        negative = true;
    }
    if (x > 90.0) x = 180.0 - x;
    double s;
    if (x == 0) s = 0;
    else if (x == 30) s = 0.5;
    else if (x == 45) s = std::numbers::sqrt2 / 2;
    else if (x == 60) s = std::numbers::sqrt3 / 2;
    else if (x == 90) s = 1;
    else if (x < 45) s = std::sin(x * (std::numbers::pi / 180.0));
    else s = std::cos((90.0 - x) * (std::numbers::pi / 180.0));  // accurate near 90°
    return negative && s != 0 ? -s : s;                          // never -0 (prints as "-0")
}

inline double cos_deg(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    return sin_deg(std::fmod(x, 360.0) + 90.0);
}

}  // namespace kerf
