// The convex hull of a point set (hull(), minkowski(): docs/lowering.md,
// "Hull, Minkowski, resize"), with its dimension: qhull (libqhull_r) for a
// full-dimensional set, kerf's own code for the flat cases qhull refuses
// (one point, collinear or coplanar points). The hull's corners are input
// points, never moved, so the hull of exact points is exact.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace kerf {

struct ConvexHull {
    int dim = -1;                      // -1: no points; 0 a point, 1 a segment, 2 a polygon, 3 a polytope
    std::vector<glm::dvec3> points;    // the corners (a subset of the input)
    // dim 3: faces as loops into `points`, counter-clockwise seen from
    // outside (coplanar facets merged), with outward unit normals.
    std::vector<std::vector<std::uint32_t>> faces;
    std::vector<glm::dvec3> normals;
    // dim 2: `points` in order around the polygon, counter-clockwise seen
    // from +normal; dim 1: `points` are the two ends.
    glm::dvec3 normal{0, 0, 1};
};

// Points within 1e-10 of the set's diameter from a line or plane through
// the others count as on it (docs/accuracy.md, "Hulls"). Throws
// std::runtime_error with qhull's message if qhull fails.
ConvexHull convex_hull(const std::vector<glm::dvec3>& points);

// The hull's volume (0 below dimension 3).
double hull_volume(const ConvexHull& h);

}  // namespace kerf
