// Adaptive anti-aliasing's straight edges (adaptive_aa.cpp, docs/quality.md): a
// candidate pixel whose corners show two surfaces, one run of corners each
// around the pixel, is crossed by one edge that enters and leaves through
// the two sides where the run changes. Where it crosses each side is found
// by bisection along the side (adaptive_aa.cpp); here, the share of the pixel on
// each side of the straight line through the two crossings.
#pragma once
#include <array>
#include <cmath>

#include <glm/glm.hpp>

namespace kerf::render {

// The pixel's corners in order round it, in pixel units: (0,0) (1,0) (1,1)
// (0,1). Side i runs from corner i to corner i + 1 (mod 4).
inline glm::dvec2 pixel_corner(int i) { return {double(i == 1 || i == 2), double(i >= 2)}; }

// Corners whose class is `a[i]`, in order round the pixel: exactly two of
// the sides change class (the caller checks), and `cross[i]`, for those,
// is where on side i the edge crosses it. Returns the area of the class-true
// part: the convex polygon of its corners and the two crossings.
inline double covered_area(const std::array<bool, 4>& a, const std::array<glm::dvec2, 4>& cross) {
    glm::dvec2 poly[6];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        if (a[i]) poly[n++] = pixel_corner(i);
        if (a[i] != a[(i + 1) % 4]) poly[n++] = cross[i];
    }
    double twice = 0;  // the shoelace formula
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % n];
        twice += p.x * q.y - q.x * p.y;
    }
    return std::abs(twice) / 2;
}

// The point (x, y) of the pixel on side `side` at `t` of its way from
// corner `side` to the next.
inline glm::dvec2 on_side(int side, double t) { return glm::mix(pixel_corner(side), pixel_corner((side + 1) % 4), t); }

// Signed distance of p from the line through p0 and p1, positive on the
// side of `ref` (a point off the line).
inline double side_distance(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 ref, glm::dvec2 p) {
    const glm::dvec2 d = p1 - p0;
    const double len = glm::length(d);
    if (len == 0) return 0;
    const double s = (d.x * (p.y - p0.y) - d.y * (p.x - p0.x)) / len;
    return d.x * (ref.y - p0.y) - d.y * (ref.x - p0.x) >= 0 ? s : -s;
}

}  // namespace kerf::render
