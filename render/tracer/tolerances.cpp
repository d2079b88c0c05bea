// The tracer's tolerances, local to each unit (docs/accuracy.md, "Far from
// the origin"). Two things limit how exactly a crossing is known: the
// solver's error relative to the leaf's own size, and the rounding of
// coordinates relative to their magnitude (o - centre in double). So the
// degenerate rule of a unit is
//     eps = kSize * size + kPosition * magnitude
// over the leaves of that unit only (size: half the box diagonal, magnitude:
// the largest |coordinate| of the box), and each ray adds kPosition * |o|
// for its own origin (make_state). One far-away part therefore no longer
// coarsens the rest of the scene, and a scene moved far from the origin
// keeps the tolerance its size asks for.
//
// Embree's float BVHs work in a frame centred on the bounded units, so that
// their rounding follows the scene's extent, not its distance from 0.
#include <algorithm>
#include <cmath>

#include "render/tracer/build.hpp"
#include "render/tracer/parallel_build.hpp"

namespace kerf::render {

namespace {

// Double: the solver is good to ~1e-9 of the leaf's size (quartics, grazing
// roots), coordinates to ~450 ulps. Float leaves (a speed option) round in
// single precision both ways.
struct Factors {
    double size, position, per_distance;
};
constexpr Factors kDouble{1e-9, 1e-13, 1e-13};
constexpr Factors kFloat{2e-5, 2e-5, 1e-6};

struct Extent {
    double size = 0, magnitude = 0;
    void add(const Extent& e) {
        size = std::max(size, e.size);
        magnitude = std::max(magnitude, e.magnitude);
    }
};

Extent leaf_extent(const csg::Leaf& leaf) {
    Extent e;
    e.magnitude = glm::length(leaf.world_from_object.offset);
    if (finite_box(leaf.bounds)) {
        e.size = 0.5 * glm::length(leaf.bounds.hi - leaf.bounds.lo);
        e.magnitude = std::max({e.magnitude, glm::length(leaf.bounds.lo), glm::length(leaf.bounds.hi)});
    } else if (leaf.kind == csg::PrimKind::Plane) {
        // A half-space's crossing is linear: only its position rounds.
        const double n = glm::length(glm::dvec3(leaf.p[0], leaf.p[1], leaf.p[2]));
        if (n > 0) e.magnitude += std::abs(leaf.p[3]) / n;
    }
    return e;
}

}  // namespace

void CsgTracer::Impl::local_tolerances(const std::vector<std::uint32_t>& units) {
    const Factors f = use_float ? kFloat : kDouble;
    eps_per_distance = f.per_distance;
    reserve_populated(node_eps, scene.nodes.size());
    reserve_populated(leaf_eps, scene.leaves.size());
    node_eps.assign(scene.nodes.size(), 0);
    leaf_eps.assign(scene.leaves.size(), 0);
    double widest = 0;
    const auto unit_eps = [&](const Extent& ext) {
        return use_float ? f.size * std::max(ext.size, ext.magnitude) : f.size * ext.size + f.position * ext.magnitude;
    };
    const auto unit_extent = [&](std::uint32_t unit) {
        Extent ext;
        if (finite_box(scene.nodes[unit].bounds)) {
            const csg::Aabb& b = scene.nodes[unit].bounds;
            ext.size = 0.5 * glm::length(b.hi - b.lo);
        }
        return ext;
    };
    // A unit's rule, on one of its nodes (and the node's leaf).
    const auto apply = [&](std::uint32_t id, double eps) {
        node_eps[id] = std::max(node_eps[id], eps);
        const csg::Node& n = scene.nodes[id];
        if (n.op == csg::Op::Leaf) leaf_eps[n.first] = std::max(leaf_eps[n.first], eps);
    };
    // A unit that is one leaf (every unit of a crowd of bare spheres) needs
    // no walk: its rule from its own box and leaf (the same max over the
    // same values).
    // A big crowd's rules are found by the arena's threads, each unit's
    // into its own slot, then applied in order as before.
    const auto leaf_unit_eps = [&](std::uint32_t unit) {
        Extent ext = unit_extent(unit);
        ext.add(leaf_extent(scene.leaves[scene.nodes[unit].first]));
        return unit_eps(ext);
    };
    std::vector<double> found;
    if (units.size() >= kParallelBuild) {
        found.assign(units.size(), 0);
        parallel_for_build(units.size(), [&](std::size_t i) {
            if (scene.nodes[units[i]].op == csg::Op::Leaf) found[i] = leaf_unit_eps(units[i]);
        });
    }
    std::vector<std::uint32_t> stack, members;
    for (std::size_t i = 0; i < units.size(); ++i) {
        const std::uint32_t unit = units[i];
        if (scene.nodes[unit].op == csg::Op::Leaf) {
            const double eps = found.empty() ? leaf_unit_eps(unit) : found[i];
            widest = std::max(widest, eps);
            apply(unit, eps);
            continue;
        }
        // The unit's subtree, iteratively (trees may be deep).
        Extent ext = unit_extent(unit);
        members.clear();
        stack.assign(1, unit);
        while (!stack.empty()) {
            const std::uint32_t id = stack.back();
            stack.pop_back();
            members.push_back(id);
            const csg::Node& n = scene.nodes[id];
            if (n.op == csg::Op::Leaf) {
                ext.add(leaf_extent(scene.leaves[n.first]));
                continue;
            }
            for (std::uint32_t k = 0; k < n.count; ++k) stack.push_back(scene.children[n.first + k]);
        }
        const double eps = unit_eps(ext);
        widest = std::max(widest, eps);
        for (std::uint32_t id : members) apply(id, eps);
    }
    // Nodes above the units (the root's union chain) are never spanned;
    // give them the widest so their padded boxes stay conservative.
    for (std::uint32_t id = 0; id < scene.nodes.size(); ++id)
        if (node_eps[id] == 0) node_eps[id] = widest;

    csg::Aabb bounded;
    for (std::uint32_t unit : units)
        if (finite_box(scene.nodes[unit].bounds)) bounded.extend(scene.nodes[unit].bounds);
    if (bounded.empty()) {
        frame = glm::dvec3(0.0);
        frame_radius = std::max(1.0, glm::length(scene.camera.position));
        return;
    }
    frame = 0.5 * (bounded.lo + bounded.hi);
    frame_radius = std::max(0.5 * glm::length(bounded.hi - bounded.lo), 1e-300);
}

double CsgTracer::surface_offset(const TraceHit& hit, const glm::dvec3& p) const {
    // Well above the degenerate rule at the hit, so a shadow or reflected
    // ray starts clear of the surface it leaves.
    return 100 * (impl_->leaf_eps[hit.surface.leaf] + impl_->eps_per_distance * glm::length(p));
}

}  // namespace kerf::render
