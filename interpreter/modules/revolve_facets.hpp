// rotate_extrude under --facets openscad (docs/openscad.md, "Facets"): the
// profile revolved in OpenSCAD 2021.01's steps. OpenSCAD joins the profile's
// copies at n meridians by flat quads; within the wedge between two
// meridians a point p is then inside exactly when (p·u / cos(Δ/2), z) is in
// the profile, u the wedge's bisector and Δ its angle — the profile
// extruded across the wedge and cut by it. So the faceted revolution is the
// union of n such pieces, each an exact prism of the profile's own CSG tree
// (the 2D booleans commute with it, as with the exact revolution).
#pragma once
#include <cstdint>
#include <vector>

#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

// Revolves the flat nodes `shapes` (taken off the pending stack, in the
// plane x = radius, y = height; mirrored: lying at x <= 0) by `angle`
// degrees in OpenSCAD's steps: the fragment count from `radius`, the
// largest |x| of the profile's region as OpenSCAD measures it (on the
// polygon after the 2D booleans), and the call's $fn, $fa, $fs, times |angle|/360, at
// least 1; meridians from −x for a full turn (+x when mirrored), from +x
// (−x) for a partial one, as OpenSCAD places them. Returns false, building
// nothing, when a step would span 180° or more (a partial angle with very
// few fragments), where OpenSCAD's quads fold over: the caller revolves
// exactly.
bool faceted_revolve(ModuleCall& c, const std::vector<std::uint32_t>& shapes, double angle, bool mirrored,
                     double radius);

// kerf's torus(R, r) as OpenSCAD would cut rotate_extrude() translate([R, 0]) circle(r).
void faceted_torus(ModuleCall& c, double R, double r);

// The node pending[mark..] (one node) limited to the wedge swept from angle
// `from` by `angle` degrees (|angle| < 360) about Z.
void cut_wedge(GraphBuilder& g, std::size_t mark, double from, double angle, const SourceLoc& loc);

}  // namespace kerf::eval
