// linear_extrude with a twist or an uneven scale under --facets openscad
// (docs/openscad.md, "Facets"): the polyhedron OpenSCAD 2021.01 builds
// instead of kerf's exact sweep. OpenSCAD unites the 2D children into one
// region, stacks `slices` flat copies of its outlines (copy j turned by
// −twist·j/slices and scaled by 1 − (1 − scale)·j/slices), joins each pair
// of neighbouring copies by two triangles per edge, split along the
// shorter diagonal, and closes the ends with the region's triangles. The
// slices bulge out of the exact sweep (linear_extrude(10, twist = 90)
// square(5): 264.656 instead of 250), so matching OpenSCAD's volumes needs
// its own cut.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

struct SliceSpec {
    double height = 1;          // the extrusion's length (the slice count depends on it)
    double twist = 0;           // degrees, OpenSCAD's sign
    glm::dvec2 scale{1, 1};     // the top section's
    double slices = 0;          // the argument; below 1 (or absent) OpenSCAD's own count
};

// OpenSCAD 2021.01's slice count for a region whose farthest vertex lies
// at squared distance r2 from the axis (a twist: the helix or, under a
// uniform scale, the conical helix that vertex follows, cut by $fs, and
// the twist cut by $fa, the fewer of the two, at least one slice per 120°;
// $fn·|twist|/360 when $fn > 0) or whose vertices move by at most
// sqrt(d2) between bottom and top (an uneven scale alone: the path cut by
// $fs, or $fn slices). A count, maybe past any limit (the caller checks).
double openscad_slices(const SliceSpec& s, double r2, double d2, const FacetVars& f);

// The polyhedron OpenSCAD builds from the flat nodes `shapes` (off the
// pending stack), on the unit slab (z = τ), pushed on the pending stack
// for the caller to map like any extrusion.
void add_openscad_slices(ModuleCall& c, const std::vector<std::uint32_t>& shapes, const SliceSpec& s);

}  // namespace kerf::eval
