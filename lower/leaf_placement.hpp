// A primitive placed in the world: the composed world_from_object affine
// becomes the leaf's three matrices and its exact world box.
#pragma once
#include <vector>

#include "grammar/source.hpp"
#include "csg/scene.hpp"

namespace kerf {

// Fills leaf.world_from_object, object_from_world, normal_to_world and
// bounds (leaf.kind and leaf.p must be set; mesh_points for Mesh leaves).
// A singular or non-finite composed transform is a SourceError at `loc`.
void place_leaf(csg::Leaf& leaf, const csg::Affine& world_from_object,
                const std::vector<glm::dvec3>* mesh_points, const SourceLoc& loc);

}  // namespace kerf
