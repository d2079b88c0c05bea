// Lowering: the scene graph becomes csg::Scene, the renderer's only
// input — flattened n-ary operations, transforms pushed into the leaves,
// clipped bounds, pruned subtrees, resolved materials and scene defaults.
#pragma once
#include "interpreter/scene_graph.hpp"
#include "csg/scene.hpp"

namespace kerf {

// Throws SourceError for scene-level problems it can locate (e.g. a
// singular transform reaching a leaf).
csg::Scene lower_to_csg(const graph::SceneGraph& graph);

}  // namespace kerf
