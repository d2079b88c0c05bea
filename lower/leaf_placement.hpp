// A primitive placed in the world: the composed world_from_object affine
// becomes the leaf's three matrices and its exact world box.
#pragma once
#include <vector>

#include "grammar/source.hpp"
#include "csg/scene.hpp"

namespace kerf {

// Fills leaf.world_from_object, object_from_world and bounds (leaf.kind and leaf.p must be set; mesh_points for Mesh leaves,
// prism_corners for Prism leaves: the box of a point set's image is exact;
// the section for Lathe leaves).
// A singular or non-finite composed transform is a SourceError at `loc`, and
// so is a box outside the renderable range (check_range).
void place_leaf(csg::Leaf& leaf, const csg::Affine& world_from_object,
                const std::vector<glm::dvec3>* mesh_points, const SourceLoc& loc,
                const csg::Polygon2* lathe_section = nullptr);

// The inverse of a regular affine map (rescaled first, so a tiny or huge
// but regular map does not under- or overflow its determinant).
csg::Affine invert(const csg::Affine& a);

// The vertices of a prism's section on both caps (parameters p: the top one scaled by 1 + p[2]).
std::vector<glm::dvec3> prism_corners(const csg::Polygon2& poly, const double* p);

// A SourceError at `loc` unless the box's finite coordinates lie within
// ±csg::kRenderableRange. (A tiny solid is fine: it is small in the picture;
// what must not be tiny is the view, see defaults.hpp and the camera.)
void check_range(const csg::Aabb& box, const SourceLoc& loc);

}  // namespace kerf
