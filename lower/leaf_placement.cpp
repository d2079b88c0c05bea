#include "lower/leaf_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "lower/mesh_lowering.hpp"
#include "lower/primitive_bounds.hpp"

namespace kerf {

namespace {

bool all_finite(const csg::Affine& a) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(a.linear[c][r])) return false;
    return std::isfinite(a.offset.x) && std::isfinite(a.offset.y) && std::isfinite(a.offset.z);
}

// |det| relative to the product of the column lengths (Hadamard's bound):
// 1 for any rotation/uniform scale, 0 for a flattening map, independent of
// the overall size so tiny or huge models are not mistaken for singular.
// (Columns are normalised first so the ratio cannot underflow.)
double volume_ratio(const glm::dmat3& m) {
    glm::dmat3 unit;
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(m[c]);
        if (!(len > 0)) return 0;
        unit[c] = m[c] / len;
    }
    return std::abs(glm::determinant(unit));
}

std::string format_range(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

// The linear part bit for bit the identity's (+0 off the diagonal).
bool identity_linear(const glm::dmat3& m) {
    static const glm::dmat3 id(1.0);
    return std::memcmp(&m, &id, sizeof m) == 0;
}

[[noreturn, gnu::noinline, gnu::cold]] void out_of_range(double far, const SourceLoc& loc) {
    throw SourceError(loc, "this solid reaches " + format_range(far) + " from the origin; kerf renders solids within " +
                               format_range(csg::kRenderableRange));
}

}  // namespace

csg::Affine invert(const csg::Affine& a) {
    // Inverting the rescaled matrix keeps the determinant from under- or
    // overflowing for very small or very large (but regular) maps.
    double size = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) size = std::max(size, std::abs(a.linear[c][r]));
    csg::Affine inv;
    inv.linear = glm::inverse(a.linear / size) / size;
    inv.offset = -(inv.linear * a.offset);
    return inv;
}

// A translated leaf (the linear part exactly the identity: most leaves of a
// loop's translate()s) skips what is known of the identity: its volume
// ratio is 1, its inverse is glm::inverse's of it (a constant: the same
// bits), and a sphere's support along the unit rows is its radius times
// sqrt(1) = 1. Everything else is what the general path computes, in its
// order, so the leaf's bits are the same (tests/lower/test_leaf_placement.cpp).
static void place_translated_leaf(csg::Leaf& leaf, const csg::Affine& wfo, const SourceLoc& loc) {
    static const glm::dmat3 inverse_of_identity = glm::inverse(glm::dmat3(1.0) / 1.0) / 1.0;
    if (!(std::isfinite(wfo.offset.x) && std::isfinite(wfo.offset.y) && std::isfinite(wfo.offset.z)))
        throw SourceError(loc, "the transforms around this primitive are not finite");
    leaf.world_from_object = wfo;
    leaf.object_from_world.linear = inverse_of_identity;
    leaf.object_from_world.offset = -(inverse_of_identity * wfo.offset);
    if (!all_finite(leaf.object_from_world))
        throw SourceError(loc, "the transforms around this primitive cannot be inverted");
    const double r = leaf.p[0];
    for (int i = 0; i < 3; ++i) {
        leaf.bounds.hi[i] = wfo.offset[i] + r;
        leaf.bounds.lo[i] = wfo.offset[i] - r;
    }
    check_range(leaf.bounds, loc);
}

void place_leaf(csg::Leaf& leaf, const csg::Affine& wfo, const std::vector<glm::dvec3>* mesh_points,
                const SourceLoc& loc, const csg::Polygon2* lathe_section) {
    if (leaf.kind == csg::PrimKind::Sphere && identity_linear(wfo.linear)) return place_translated_leaf(leaf, wfo, loc);
    if (!all_finite(wfo)) throw SourceError(loc, "the transforms around this primitive are not finite");
    if (!(volume_ratio(wfo.linear) > 1e-12))
        throw SourceError(loc, "the transforms around this primitive are singular (they flatten it to zero volume)");
    leaf.world_from_object = wfo;
    leaf.object_from_world = invert(wfo);
    if (!all_finite(leaf.object_from_world))
        throw SourceError(loc, "the transforms around this primitive cannot be inverted");
    // Normals map by the inverse transpose (Leaf::normal_to_world), which
    // keeps them outward under mirrors too: for an outward step v
    // (n·v > 0), (L⁻ᵀn)·(L v) = n·v > 0.
    if (leaf.kind == csg::PrimKind::Mesh || leaf.kind == csg::PrimKind::Prism)
        leaf.bounds = mesh_points ? mesh_bounds(*mesh_points, wfo) : csg::Aabb{};
    else if (leaf.kind == csg::PrimKind::Lathe)
        leaf.bounds = lathe_section ? lathe_bounds(*lathe_section, wfo) : csg::Aabb{};
    else if (leaf.kind == csg::PrimKind::Plane)
        leaf.bounds = clip_by_halfspace(csg::Aabb::everything(), world_halfspace(leaf));
    else
        leaf.bounds = primitive_bounds(leaf.kind, leaf.p, wfo);
    check_range(leaf.bounds, loc);
}

std::vector<glm::dvec3> prism_corners(const csg::Polygon2& poly, const double* p) {
    std::vector<glm::dvec3> out;
    out.reserve(4 * poly.edges.size());
    if (p[4] != 0) {
        // Twisted: every section lies in the disc of radius max|v|·max(kx, ky),
        // at most the interpolation of the caps' radii (a max of linear
        // functions is convex), so the squares around the caps' discs hold it.
        double r = 0;
        for (const glm::dvec4& e : poly.edges) r = std::max({r, std::hypot(e.x, e.y), std::hypot(e.z, e.w)});
        for (int cap = 0; cap < 2; ++cap) {
            const double k = cap ? std::max(1 + p[2], 1 + p[2] + p[3]) : 1;
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) out.emplace_back(sx * k * r, sy * k * r, p[cap]);
        }
        return out;
    }
    // Each section point moves linearly from its bottom copy to its top one
    // (scaled by kx, ky): the caps' vertices' hull holds the solid.
    for (const glm::dvec4& e : poly.edges)
        for (int cap = 0; cap < 2; ++cap) {
            const double kx = cap ? 1 + p[2] : 1, ky = cap ? 1 + p[2] + p[3] : 1;  // the top section's scales
            out.emplace_back(kx * e.x, ky * e.y, p[cap]);
            out.emplace_back(kx * e.z, ky * e.w, p[cap]);
        }
    return out;
}

void check_range(const csg::Aabb& box, const SourceLoc& loc) {
    // (`far` in a register, the message out of line: the string building
    // kept it on the stack, a store and a load per side, 1.6 % of a
    // 10^5-sphere front end.)
    double far = 0;
    for (int i = 0; i < 3; ++i) {
        // Unbounded sides (half-spaces) are fine; what is finite must fit.
        const double lo = std::abs(box.lo[i]), hi = std::abs(box.hi[i]);
        if (std::isfinite(lo) && lo > far) far = lo;
        if (std::isfinite(hi) && hi > far) far = hi;
    }
    if (far > csg::kRenderableRange) out_of_range(far, loc);
}

}  // namespace kerf
