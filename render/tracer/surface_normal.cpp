// CsgTracer::normal: the final solid's world unit normal at a hit. The hit's
// span end names the leaf surface (and mesh triangle) and whether the CSG
// flipped it (a subtrahend's surface faces into the minuend).
#include <cmath>

#include "render/primitives/kinds.hpp"
#include "render/primitives/primitives.hpp"
#include "render/primitives/lathe.hpp"
#include "render/primitives/prism.hpp"
#include "render/tracer/build.hpp"

namespace kerf::render {

glm::dvec3 CsgTracer::normal(const TraceHit& hit, const glm::dvec3& world_point) const {
    const csg::Leaf& leaf = impl_->scene.leaves[hit.surface.leaf];
    // A leaf only moved (most are) skips both matrices, as its spans do
    // (analytic_spans.hpp): 1·x + 0·y + 0·z is x, so the numbers are the
    // same (up to the sign of a zero component, which no output sees).
    const bool shift = impl_->leaf_shift_only[hit.surface.leaf];
    const std::uint8_t part = hit.surface.part;
    // A moved box's face normal is a unit axis already: n / |n| is n, bit
    // for bit (a holed plate's top and sides).
    if (shift && leaf.kind == csg::PrimKind::Box && part < 6) {
        const glm::dvec3 n = csg::normal_box(leaf.p, world_point, part);
        return hit.surface.flip ? -n : n;
    }
    const glm::dvec3 q = impl_->leaf_point(hit.surface.leaf, world_point);
    // A moved sphere's normal (a lattice's): the object normal is q itself
    // (csg::normal_sphere), here without object_normal's two calls and
    // switch; the same length and divisions below.
    if (shift && leaf.kind == csg::PrimKind::Sphere) {
        const double len = glm::length(q);
        const glm::dvec3 n = len > 0 ? q / len : glm::dvec3(0, 0, 1);
        return hit.surface.flip ? -n : n;
    }
    // A moved straight cylinder's side (a drilled hole's wall): the
    // general path's (x, y, -0·ρ) / sqrt(x² + y² + 0) with one square root
    // instead of two (ρ and the length are the same number).
    if (shift && leaf.kind == csg::PrimKind::Cylinder && part == csg::kPartSide && leaf.p[2] == leaf.p[3]) {
        const double r2 = q.x * q.x + q.y * q.y;
        if (r2 > 0) {
            const double len = std::sqrt(r2);
            const glm::dvec3 n(q.x / len, q.y / len, -0.0);
            return hit.surface.flip ? -n : n;
        }
    }
    const glm::dvec3 n_obj =
        leaf.kind == csg::PrimKind::Mesh    ? triangle_normal(impl_->scene.meshes[leaf.mesh], hit.surface.prim)
        : leaf.kind == csg::PrimKind::Prism ? csg::normal_prism(impl_->scene.polygons[leaf.polygon], leaf.p, hit.surface.part,
                                                                hit.surface.prim, q)
        : leaf.kind == csg::PrimKind::Lathe ? csg::normal_lathe(impl_->scene.polygons[leaf.polygon], hit.surface.part,
                                                                hit.surface.prim, q)
                                            : csg::object_normal(leaf, q, hit.surface.part);
    glm::dvec3 n = shift ? n_obj : leaf.normal_to_world(n_obj);
    const double len = glm::length(n);
    n = len > 0 ? n / len : glm::dvec3(0, 0, 1);
    return hit.surface.flip ? -n : n;
}

}  // namespace kerf::render
