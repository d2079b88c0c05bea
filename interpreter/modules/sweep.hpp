// linear_extrude with a twist or a scale that differs in x and y
// (docs/spec.md §10): the section map S(τ)·R(−θτ) does not commute with the
// 2D transforms, but it does with the 2D booleans (a point is in the
// extrusion of A ∪ B exactly when its preimage is in A ∪ B). So, as for
// rotate_extrude, the subtree is rebuilt with every transform applied to
// its leaves (docs/lowering.md, "Swept extrusions").
#pragma once
#include <cstdint>

#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

struct SweepMap {
    double sx = 1, sy = 1;  // the top section's scales
    double twist = 0;       // radians, positive clockwise seen from +Z (OpenSCAD's)
};

// The swept copy of 2D node `id` (on the unit slab) pushed on the builder's
// pending stack: polygons and squares a swept Prism over their mapped edges;
// a circle that stays a circle about the origin under a uniform scale a
// cylinder or cone (a twist turns it onto itself), any other circle a
// polygon within the curve tolerance. A hull or minkowski below is done in
// the plane first (flat_hull_ops.hpp), its convex polygons swept; a resize
// is its scale.
void sweep_subtree(ModuleCall& c, std::uint32_t id, const SweepMap& map);

}  // namespace kerf::eval
