// What `$fn`, `$fa` and `$fs` do to a curve under --facets (docs/openscad.md,
// "Facets"). auto: an explicit `$fn` from 3 to 12 on a circle or cylinder
// call makes OpenSCAD's regular polygon (the hex nut), every other curve
// stays exact. exact: every curve stays exact. openscad: every curve is cut
// as OpenSCAD 2021.01 cuts it — its fragment rule, its vertex placement.
#pragma once
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

// The facet count to honour for this call, or 0 to keep the curve exact:
// --facets auto's explicit $fn from 3 to 12; --facets openscad's fragment
// count for a curve of radius r (openscad_fragments); 0 under exact.
int honoured_facets(const ModuleCall& c, double r = 0);

// OpenSCAD 2021.01's get_fragments_from_r: 3 for a radius below its fine
// grid; max($fn, 3) when $fn > 0; otherwise ceil(max(min(360/$fa,
// 2πr/$fs), 5)). Throws (located at the call) when the count passes the
// list limit, so a huge $fn ends in an error, not in exhausted memory.
int openscad_fragments(const ModuleCall& c, double r, const FacetVars& f);

// A flat prism over the regular n-gon of radius r, vertices at angles
// 360·i/n from +x as OpenSCAD places them, tapered by `taper` (the top
// section's scale minus 1, as linear_extrude's) on the unit slab.
void add_regular_prism(ModuleCall& c, int n, double r, double taper = 0);

// OpenSCAD 2021.01's sphere of n fragments as a polyhedron: (n + 1) / 2
// rings at latitudes 180°·(i + ½)/rings from the north pole, each the
// regular n-gon with a vertex on +x, a flat cap at each end.
void add_openscad_sphere(ModuleCall& c, int n, double r);

}  // namespace kerf::eval
