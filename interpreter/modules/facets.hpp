// OpenSCAD's coarse facets where they are the design (docs/openscad.md,
// "Facets"): an explicit `$fn` from 3 to 12 on a circle or cylinder call
// makes OpenSCAD's regular polygon (the hex nut), every other curve stays
// exact.
#pragma once
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

// The facet count to honour for this call, or 0 to keep the curve exact.
int honoured_facets(const ModuleCall& c);

// A flat prism over the regular n-gon of radius r, vertices at angles
// 360·i/n from +x as OpenSCAD places them, tapered by `taper` (the top
// section's scale minus 1, as linear_extrude's) on the unit slab.
void add_regular_prism(ModuleCall& c, int n, double r, double taper = 0);

}  // namespace kerf::eval
