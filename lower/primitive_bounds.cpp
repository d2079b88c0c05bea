#include "lower/primitive_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf {

namespace {

double len_xy(const glm::dvec3& w) { return std::hypot(w.x, w.y); }

// Paraboloid z >= h ρ²/r², z <= h. Along a generatrix ρ = r·sqrt(z/h), and
// w·u = a ρ + w_z z with a = |w_xy|: concave in z, so the maximum is the cap
// rim (w_z >= 0 or the stationary point lies above the cap) or the stationary
// point z* = a² r² / (4 h w_z²), where the value is a² r² / (4 h |w_z|).
double paraboloid_support(double h, double r, const glm::dvec3& w) {
    const double a = len_xy(w);
    const double rim = a * r + w.z * h;
    if (w.z >= 0) return rim;
    const double zs = a * a * r * r / (4 * h * w.z * w.z);
    if (zs >= h) return rim;
    return a * a * r * r / (4 * h * -w.z);
}

// The box [c_i − h(−row_i L), c_i + h(row_i L)] of support function h under the map.
template <class Support>
csg::Aabb support_bounds(const csg::Affine& world_from_object, const Support& h) {
    csg::Aabb box;
    const glm::dmat3& m = world_from_object.linear;
    for (int i = 0; i < 3; ++i) {
        // Row i of L (GLM is column-major: m[col][row]).
        const glm::dvec3 row(m[0][i], m[1][i], m[2][i]);
        box.hi[i] = world_from_object.offset[i] + h(row);
        box.lo[i] = world_from_object.offset[i] - h(-row);
    }
    return box;
}

}  // namespace

double primitive_support(csg::PrimKind kind, const double p[6], const glm::dvec3& w) {
    switch (kind) {
        case csg::PrimKind::Sphere:
            return p[0] * glm::length(w);
        case csg::PrimKind::Box:
            return std::max(w.x * p[0], w.x * p[3]) + std::max(w.y * p[1], w.y * p[4]) +
                   std::max(w.z * p[2], w.z * p[5]);
        case csg::PrimKind::Cylinder: {
            // Convex hull of the two cap disks.
            const double a = len_xy(w);
            return std::max(p[0] * w.z + p[2] * a, p[1] * w.z + p[3] * a);
        }
        case csg::PrimKind::Torus:
            // Torus = circle of radius R (in XY) ⊕ ball of radius r.
            return p[0] * len_xy(w) + p[1] * glm::length(w);
        case csg::PrimKind::Paraboloid:
            return paraboloid_support(p[0], p[1], w);
        case csg::PrimKind::Hyperboloid:
            // Radius grows monotonically from the waist to r at z = ±h/2, so the
            // hull is the hull of the two cap disks: a cylinder of radius r.
            // (max() keeps a waist wider than the caps, which the spec does
            // not allow, at least conservative.)
            return std::max(p[1], p[2]) * len_xy(w) + 0.5 * p[0] * std::abs(w.z);
        case csg::PrimKind::Plane:
        case csg::PrimKind::Mesh:
        case csg::PrimKind::Prism:  // bounded from its own 2D data (leaf_placement, lathe_bounds)
        case csg::PrimKind::Lathe:
            break;
    }
    return std::numeric_limits<double>::infinity();
}

csg::Aabb primitive_bounds(csg::PrimKind kind, const double p[6], const csg::Affine& world_from_object) {
    if (kind == csg::PrimKind::Plane) {
        csg::Leaf leaf;
        leaf.kind = kind;
        std::copy(p, p + 6, leaf.p);
        // world_halfspace needs object_from_world; only its linear part and
        // offset matter, recomputed here from the forward map.
        leaf.object_from_world.linear = glm::inverse(world_from_object.linear);
        leaf.object_from_world.offset = -(leaf.object_from_world.linear * world_from_object.offset);
        return clip_by_halfspace(csg::Aabb::everything(), world_halfspace(leaf));
    }
    return support_bounds(world_from_object, [&](const glm::dvec3& w) { return primitive_support(kind, p, w); });
}

// The hull of a solid of revolution is the hull of its vertices' circles,
// and the circle of radius r at height z has support r·|w_xy| + z·w_z.
csg::Aabb lathe_bounds(const csg::Polygon2& poly, const csg::Affine& world_from_object) {
    return support_bounds(world_from_object, [&](const glm::dvec3& w) {
        double h = -std::numeric_limits<double>::infinity();
        const double a = len_xy(w);
        for (const glm::dvec4& e : poly.edges) h = std::max({h, e.x * a + e.y * w.z, e.z * a + e.w * w.z});
        return h;
    });
}

HalfSpace world_halfspace(const csg::Leaf& leaf) {
    // n·(A x + b) <= d  <=>  (Aᵀ n)·x <= d − n·b
    const glm::dvec3 n(leaf.p[0], leaf.p[1], leaf.p[2]);
    const csg::Affine& ofw = leaf.object_from_world;
    return {glm::transpose(ofw.linear) * n, leaf.p[3] - glm::dot(n, ofw.offset)};
}

csg::Aabb clip_by_halfspace(const csg::Aabb& box, const HalfSpace& h) {
    if (box.empty()) return box;
    // Smallest value of n_j x_j over the box on each axis (a zero coefficient
    // contributes nothing, even on an infinite side).
    double low[3];
    for (int j = 0; j < 3; ++j)
        low[j] = h.normal[j] == 0 ? 0 : std::min(h.normal[j] * box.lo[j], h.normal[j] * box.hi[j]);
    csg::Aabb out = box;
    for (int i = 0; i < 3; ++i) {
        const double rest = low[(i + 1) % 3] + low[(i + 2) % 3];
        const double n = h.normal[i];
        // Feasible x_i: n x_i + rest <= offset.
        if (n > 0) {
            out.hi[i] = std::min(out.hi[i], (h.offset - rest) / n);
        } else if (n < 0) {
            out.lo[i] = std::max(out.lo[i], (h.offset - rest) / n);
        } else if (rest > h.offset) {
            return csg::Aabb{};
        }
    }
    return out.empty() ? csg::Aabb{} : out;
}

}  // namespace kerf
