// Exact ray–primitive intervals in object space. The ray is
// o + t·d with d NOT normalised (it is the world direction mapped by the
// leaf's object_from_world), so t is shared by every leaf along a world ray.
// Spans cover the whole line, t in (-inf, inf): a ray that starts inside a
// solid simply sees a span with t0 < tnear, and half-spaces give infinite ends.
#pragma once
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::csg {

// The ray is inside the solid for t in [t0, t1]. part0/part1 name the surface
// piece hit at each end (e.g. side or cap), for object_normal().
template <typename T>
struct Span {
    T t0, t1;
    std::uint8_t part0, part1;
};

constexpr int kMaxSpans = 2;  // every analytic primitive: at most 2 spans per line

// Sorted, disjoint spans of positive length (tangent/zero-length contacts are
// dropped: see docs/accuracy.md for the degenerate-case rule). Returns count.
// Only the window [wa, wb] is asked for: a solver may then report a span end
// that lies outside the window at any value outside it (on the same side),
// instead of finding it exactly; ends inside the window are exact. (The
// torus uses this to skip the roots of its quartic the window does not need.)
template <typename T>
int intersect_leaf(const Leaf& leaf, const glm::vec<3, T>& o, const glm::vec<3, T>& d, Span<T> out[kMaxSpans],
                   T wa = -std::numeric_limits<T>::infinity(), T wb = std::numeric_limits<T>::infinity());

// intersect_leaf<double> of a sphere leaf along n rays (object space) in one
// loop, so the rays' chains of divisions and square roots overlap: ray k's
// spans at out[k·kMaxSpans], their count at count[k].
void intersect_sphere_rays(const Leaf& leaf, int n, const glm::dvec3* o, const glm::dvec3* d, Span<double>* out,
                           int* count);

// Outward object-space normal (not necessarily unit) at p on surface `part`.
glm::dvec3 object_normal(const Leaf& leaf, const glm::dvec3& p, std::uint8_t part);

}  // namespace kerf::csg
