// Sine and cosine of an angle in degrees, as OpenSCAD computes them: the
// angle is folded into [0°, 90°] first, so the angles people type (0, 30,
// 45, 60, 90 and every multiple) give exact values and sin(180) is -0, not
// 1.2e-16. One definition for both rotate() and the sin()/cos() built-ins,
// so a multmatrix written with sin() is the same solid as rotate().
// rotate([x, y, z])'s matrix is here too, for the viewport's $vpr.
#pragma once
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/glm.hpp>

namespace kerf {

// x in [0, 360), as OpenSCAD folds it: a whole negative turn is +0, while
// -0 itself stays -0.
inline double fold_degrees(double x) {
    const double r = std::fmod(x, 360.0);
    return r < 0 ? r + 360.0 : r == 0 && x != 0 ? 0.0 : r;
}

// The signs of zero are OpenSCAD's too (measured: sin(180) and sin(-180)
// are -0, so atan2(sin(-180), cos(-180)) is -180; cos(90) is 0, cos(270)
// -0; sin(-0) is -0); echo prints -0 as 0 in both.
inline double sin_deg(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    x = fold_degrees(x);
    bool negative = false;
    if (x >= 180.0) {
        x -= 180.0;
        negative = true;
    }
    if (x > 90.0) x = 180.0 - x;
    double s;
    if (x == 0) s = x;  // keeps the sign of -0
    else if (x == 30) s = 0.5;
    else if (x == 45) s = std::numbers::sqrt2 / 2;
    else if (x == 60) s = std::numbers::sqrt3 / 2;
    else if (x == 90) s = 1;
    else if (x < 45) s = std::sin(x * (std::numbers::pi / 180.0));
    else s = std::cos((90.0 - x) * (std::numbers::pi / 180.0));  // accurate near 90°
    return negative ? -s : s;
}

inline double cos_deg(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    x = fold_degrees(x);
    bool negative = false;
    if (x >= 180.0) {
        x -= 180.0;
        negative = true;
    }
    if (x > 90.0) {
        x = 180.0 - x;
        negative = !negative;
    }
    double c;
    if (x == 0) c = 1;
    else if (x == 30) c = std::numbers::sqrt3 / 2;
    else if (x == 45) c = std::numbers::sqrt2 / 2;
    else if (x == 60) c = 0.5;
    else if (x == 90) c = 0;
    else if (x > 45) c = std::sin((90.0 - x) * (std::numbers::pi / 180.0));  // accurate near 90°
    else c = std::cos(x * (std::numbers::pi / 180.0));
    return negative ? -c : c;
}

// A rotation by `d` degrees turning axis i towards axis j (column-major:
// row r, column k is m[k][r]); about x, y and z below.
inline glm::dmat4 rot_plane(double d, int i, int j) {
    const double c = cos_deg(d), s = sin_deg(d);
    glm::dmat4 m(1.0);
    m[i][i] = c, m[i][j] = s;
    m[j][i] = -s, m[j][j] = c;
    return m;
}
inline glm::dmat4 rot_x(double d) { return rot_plane(d, 1, 2); }
inline glm::dmat4 rot_y(double d) { return rot_plane(d, 2, 0); }
inline glm::dmat4 rot_z(double d) { return rot_plane(d, 0, 1); }

// rotate([x, y, z]): about x first, then y, then z.
inline glm::dmat4 euler_rotation(const glm::dvec3& deg) { return rot_z(deg.z) * rot_y(deg.y) * rot_x(deg.x); }

}  // namespace kerf
