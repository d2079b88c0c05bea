// The first step of lowering when a graph has hull(), minkowski() or
// resize() nodes (docs/lowering.md, "Hull, Minkowski, resize"): a copy of
// the graph in which each of them is replaced by ordinary nodes — a hull by
// a convex Mesh leaf (or the exact rounded solid of convex_solid.hpp), a
// Minkowski sum by the union of its convex pieces' sums, a resize by the
// scale OpenSCAD computes from the child's exact box.
#pragma once
#include "interpreter/scene_graph.hpp"

namespace kerf {

// False (and `out` untouched) when the graph has none of these nodes.
// Throws SourceError at the operation (or the leaf) it cannot build.
bool resolve_geometry_ops(const graph::SceneGraph& g, graph::SceneGraph& out);

}  // namespace kerf
