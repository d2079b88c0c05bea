// Tight world boxes of transformed primitives (lowering). Every
// analytic primitive has a cheap closed-form support function h(w) = max over
// the solid of w·u; for x = L u + c the world extent along axis i is
// [c_i − h(−row_i L), c_i + h(row_i L)], which is the exact box under any
// affine map (a box only sees the convex hull, and h is the hull's support).
#pragma once
#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf {

// Support function of the object-space solid (not meaningful for Plane/Mesh).
double primitive_support(csg::PrimKind kind, const double p[6], const glm::dvec3& w);

// Exact world box of an analytic primitive (Plane: its half-space's box,
// unbounded except along an axis its world normal is exactly parallel to).
csg::Aabb primitive_bounds(csg::PrimKind kind, const double p[6], const csg::Affine& world_from_object);

// Exact world box of a Lathe leaf over section `poly`.
csg::Aabb lathe_bounds(const csg::Polygon2& poly, const csg::Affine& world_from_object);

// A world half-space {x : dot(normal, x) <= offset}.
struct HalfSpace {
    glm::dvec3 normal{0, 0, 1};
    double offset = 0;
};

// The world half-space of a Plane leaf (object normal pulled back through
// object_from_world).
HalfSpace world_halfspace(const csg::Leaf& plane_leaf);

// The exact box of (box ∩ half-space); works with infinite box sides.
csg::Aabb clip_by_halfspace(const csg::Aabb& box, const HalfSpace& h);

}  // namespace kerf
