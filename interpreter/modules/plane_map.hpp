// The action of a 2D subtree's transforms in the plane (docs/spec.md §10:
// only x and y are used) as one homogeneous 3×3 map, shared by the
// operations that rebuild a 2D subtree with its transforms applied to the
// leaves (rotate_extrude, offset, linear_extrude with a twist or a scale
// differing in x and y), and a circle as the polygon whose chords stay
// within the curve tolerance.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace kerf::eval {

// x' = A·(x, y, 1), homogeneous 2D (GLM: column-major).
using Map2 = glm::dmat3;

inline Map2 plane_part(const glm::dmat4& m) {
    Map2 a(1.0);
    a[0] = {m[0][0], m[0][1], 0};
    a[1] = {m[1][0], m[1][1], 0};
    a[2] = {m[3][0], m[3][1], 1};
    return a;
}

inline glm::dvec2 apply(const Map2& a, glm::dvec2 p) { return glm::dvec2(a * glm::dvec3(p, 1)); }

// Chords of a regular polygon inscribed in a circle whose sagitta stays
// within `tolerance` times the radius.
inline int circle_segments(double tolerance) {
    return int(std::ceil(std::numbers::pi / std::acos(1 - std::min(tolerance, 0.5))));
}

// The chords of the circle of radius r about the origin, each within
// tolerance·r of the arc: edge(p, q) per chord.
template <typename Edge>
void circle_chords(double r, double tolerance, Edge&& edge) {
    const int segments = circle_segments(tolerance);
    for (int i = 0; i < segments; ++i) {
        const double t0 = 2 * std::numbers::pi * i / segments, t1 = 2 * std::numbers::pi * (i + 1) / segments;
        edge(r * glm::dvec2(std::cos(t0), std::sin(t0)), r * glm::dvec2(std::cos(t1), std::sin(t1)));
    }
}

}  // namespace kerf::eval
