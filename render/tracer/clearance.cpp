// "Is this world point clearly outside that node?" — lower bounds on the
// distance from a point to a solid, for the fast path of a difference asked
// for its first entry (or any span): when the minuend's entry point is
// farther than the degenerate rule's reach from every subtrahend, it is the
// entry, and no subtrahend is intersected at all (README.md, "Tracer
// design"). A false answer only means "not proven": the caller then gathers
// spans as before, so every bound here may be loose but never too large.
#include <algorithm>
#include <cmath>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

using csg::Node;
using csg::Op;
using csg::PrimKind;

// Whether the object-space distance from q to the primitive is provably
// more than m >= 0 (q outside it); false when inside or not known (meshes,
// quadrics without a simple bound: their box is all we use). Where the
// distance is a square root minus a radius, the squares are compared
// instead: one square root less on the fast path of every ray that meets a
// grooved solid. Solids of revolution use the meridian plane: for points
// P, Q at (ρ, z) coordinates, |P - Q| is at least the 2D distance of their
// (ρ, z), so a 2D bound of the meridian section is a 3D bound.
bool object_clear(const csg::Leaf& leaf, const glm::dvec3& q, double m) {
    const double* c = leaf.p;
    switch (leaf.kind) {
        case PrimKind::Sphere: {
            const double r = c[0] + m;
            return glm::dot(q, q) > r * r;
        }
        case PrimKind::Box: {
            const glm::dvec3 lo(c[0], c[1], c[2]), hi(c[3], c[4], c[5]);
            const glm::dvec3 out = glm::max(glm::max(lo - q, q - hi), glm::dvec3(0.0));
            return glm::dot(out, out) > m * m;
        }
        case PrimKind::Cylinder: {  // frustum: radius c[2] at z = c[0], c[3] at z = c[1]
            const double h = c[1] - c[0], dr = c[3] - c[2];
            if (!(h > 0)) return false;
            if (c[0] - q.z > m || q.z - c[1] > m) return true;
            if (dr == 0) {  // a straight one (a drilled hole): squares, no root
                const double r = c[2] + m;
                return q.x * q.x + q.y * q.y > r * r;
            }
            const double rho = std::sqrt(q.x * q.x + q.y * q.y);
            // Signed distance to the side line's outer half-plane, and to the slab.
            const double side = ((rho - c[2]) * h - (q.z - c[0]) * dr) / std::sqrt(h * h + dr * dr);
            return std::max({side, c[0] - q.z, q.z - c[1]}) > m;
        }
        case PrimKind::Torus: {
            const double e = std::sqrt(q.x * q.x + q.y * q.y) - c[0], r = c[1] + m;
            return e * e + q.z * q.z > r * r;
        }
        case PrimKind::Plane: {
            const double nn = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            return (c[0] * q.x + c[1] * q.y + c[2] * q.z - c[3]) / nn > m;
        }
        case PrimKind::Paraboloid:
        case PrimKind::Hyperboloid:
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: return false;
    }
    return false;
}

// Whether the ball of radius m >= 0 round q lies inside the one-span
// primitive (sphere, box, cylinder or frustum; false for others or when
// not proven), the mirror of object_clear.
bool object_inside(const csg::Leaf& leaf, const glm::dvec3& q, double m) {
    const double* c = leaf.p;
    switch (leaf.kind) {
        case PrimKind::Sphere: {
            const double r = c[0] - m;
            return r > 0 && glm::dot(q, q) < r * r;
        }
        case PrimKind::Box:
            return c[0] + m < q.x && q.x < c[3] - m && c[1] + m < q.y && q.y < c[4] - m && c[2] + m < q.z &&
                   q.z < c[5] - m;
        case PrimKind::Cylinder: {
            const double h = c[1] - c[0], dr = c[3] - c[2];
            if (!(h > 0) || !(c[0] + m < q.z && q.z < c[1] - m)) return false;
            if (dr == 0) {
                const double r = c[2] - m;
                return r > 0 && q.x * q.x + q.y * q.y < r * r;
            }
            const double rho = std::sqrt(q.x * q.x + q.y * q.y);
            return ((rho - c[2]) * h - (q.z - c[0]) * dr) / std::sqrt(h * h + dr * dr) < -m;
        }
        default: return false;
    }
}

}  // namespace

bool inside_by(const CsgTracer::Impl& impl, std::uint32_t node, const glm::dvec3& x, double margin) {
    const Node& n = impl.scene.nodes[node];
    if (n.op != Op::Leaf) return false;
    // The world ball of radius margin maps into the object ball of radius
    // margin·|object_from_world| (clear_of_within_box).
    const csg::Leaf& leaf = impl.scene.leaves[n.first];
    return object_inside(leaf, impl.leaf_point(n.first, x), margin * impl.leaf_stretch[n.first]);
}

bool RayState::clear_of_within_box(std::uint32_t node, const glm::dvec3& x, double margin) const {
    const Node& n = impl->scene.nodes[node];
    const std::uint32_t* kids = n.op == Op::Leaf ? nullptr : impl->scene.children.data() + n.first;
    switch (n.op) {
        case Op::Leaf: {
            // World distance >= object distance / |object_from_world| (the
            // Frobenius norm bounds the spectral one), precomputed per leaf.
            const csg::Leaf& leaf = impl->scene.leaves[n.first];
            return object_clear(leaf, impl->leaf_point(n.first, x), margin * impl->leaf_stretch[n.first]);
        }
        case Op::Union:
            // A big union is left to its BVH: checking every child would cost
            // more than the spans it saves.
            if (impl->accel_of_node[node] >= 0) return false;
            for (std::uint32_t k = 0; k < n.count; ++k)
                if (!clear_of(kids[k], x, margin)) return false;
            return true;
        case Op::Intersection:
            for (std::uint32_t k = 0; k < n.count; ++k)
                if (clear_of(kids[k], x, margin)) return true;
            return false;
        case Op::Difference: return clear_of(kids[0], x, margin);
    }
    return false;
}

}  // namespace kerf::render
