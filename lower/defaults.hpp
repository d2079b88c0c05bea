// docs/spec.md §6 scene defaults applied by lowering, so that a solid-only script
// (an OpenSCAD file) renders: a camera framing the solid, two lights.
#pragma once
#include <vector>

#include "csg/scene.hpp"
#include "grammar/source.hpp"

namespace kerf {

// A non-empty box with every coordinate finite.
bool finite_box(const csg::Aabb& b);

// The box the default camera frames: the root's bounds when finite; when a
// half-space makes the root unbounded, the union of the finite leaf boxes;
// with no finite box at all (empty scene, only planes), the cube [-1, 1]³.
csg::Aabb framing_box(const csg::Scene& scene);

// Looks at the box centre from direction [1, -1, 0.8], far enough that the
// box's bounding sphere fits the vertical field of view (40°) with a 5%
// margin — so the box is framed for any image at least as wide as it is
// tall (the default 800×600 included), at any size in the renderable range.
// A box under 1e-30 across (csg::kRenderableRange), or too small for its
// distance from the origin to be seen apart from it (size below 1e-12 of
// the distance), is a SourceError at `loc`.
csg::Camera default_camera(const csg::Aabb& frame, const SourceLoc& loc);

// A key light above and to the left of the camera, and a weak headlight at
// the camera.
std::vector<csg::Light> default_lights(const csg::Camera& camera);

}  // namespace kerf
