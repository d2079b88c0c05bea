// What a solid contributes to hull() and minkowski() (docs/lowering.md,
// "Hull, Minkowski, resize"): a convex piece, i.e. points whose hull,
// grown by a ball of `radius`, is the piece's convex hull. Exact for
// boxes, meshes, prisms (their corners) and spheres under a similarity (a
// centre and a radius); other curved solids are tessellated with chords
// within `tolerance` of their radius (docs/accuracy.md, "Hulls").
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/scene_graph.hpp"

namespace kerf {

struct ConvexPiece {
    std::vector<glm::dvec3> points;
    double radius = 0;
    bool exact = true;  // false: a tessellated curve
    // The radius is a disc's in the XY plane, not a ball's: a 2D circle on
    // its unit slab (scene_graph.hpp), the hull of its axis grown by it.
    bool disc = false;
};

// The piece of primitive node `leaf` placed by `xf` (its linear part as
// glm::dmat3, offset as translation). A half-space is a SourceError at the
// leaf (unbounded).
ConvexPiece leaf_piece(const graph::SceneGraph& g, const graph::Node& leaf, const glm::dmat4& xf, double tolerance);

// True when m is a rotation (or mirror) times a uniform scale s (set): a
// sphere under it stays a sphere of radius s·r.
bool similarity(const glm::dmat3& m, double& s);

// True when m keeps z and is a similarity s (set) in the XY plane: a 2D
// transform under which a circle stays a circle.
bool planar_similarity(const glm::dmat3& m, double& s);

// The tessellation of a sphere of radius r about the origin: rings of
// circle_segments(tolerance) points.
std::vector<glm::dvec3> sphere_points(double r, double tolerance);

// Segments per full circle so that chords stay within `tolerance` × radius
// of the circle.
int circle_segments(double tolerance);

}  // namespace kerf
