// Sine and cosine of an angle in degrees, as OpenSCAD computes them: the
// angle is folded into [0°, 90°] first, so the angles people type (0, 30,
// 45, 60, 90 and every multiple) give exact values and sin(180) is 0, not
// 1.2e-16. One definition for both rotate() and the sin()/cos() built-ins,
// so a multmatrix written with sin() is the same solid as rotate().
// rotate([x, y, z])'s matrix is here too, for the viewport's $vpr.
#pragma once
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/glm.hpp>

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
