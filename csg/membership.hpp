// Point membership and distance to the surface for analytic primitives,
// straight from each solid's defining inequalities. Written independently of
// the ray code on purpose: it is the oracle the tests check spans against.
#pragma once
#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::csg {

// True when p (object space) is strictly inside the solid. The boundary is
// outside, matching the span rule (tangent contacts are no span). Meshes:
// always false (they have no analytic inequality).
bool contains(const Leaf& leaf, const glm::dvec3& p_object);

// Prism leaves (PrimKind::Prism, parameters c) over section `poly`.
bool contains_prism(const Polygon2& poly, const double* c, const glm::dvec3& p_object);

// Lathe leaves (PrimKind::Lathe) over section `poly`: the point turned back
// into the (ρ, z) half-plane, then the even-odd rule.
bool contains_lathe(const Polygon2& poly, const glm::dvec3& p_object);

// The even-odd rule for the point (px, py) and the polygon set.
bool even_odd(const Polygon2& poly, double px, double py);

// True when the world point p is strictly inside the scene's solid: each
// node's defining rule applied to its children (union: any; intersection:
// all, and at least one child; difference: the minuend and no subtrahend).
bool contains(const Scene& scene, const glm::dvec3& p_world);

// Signed distance to the surface (negative inside): exact where simple
// (sphere, box, torus, plane, cylinder/cone), otherwise max over the solid's
// constraints of implicit value / gradient length, which is first-order
// exact near the surface. Meshes: +inf.
double surface_distance(const Leaf& leaf, const glm::dvec3& p_object);

}  // namespace kerf::csg
