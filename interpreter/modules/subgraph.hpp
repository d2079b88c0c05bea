// A subtree of the graph being built, copied out into a graph of its own,
// and a graph appended back: how projection() hands its children to
// lowering's hull(), minkowski() and resize() (EvalOptions::
// resolve_geometry_ops) and projects what comes back (docs/lowering.md,
// "Projection").
#pragma once
#include <cstdint>

#include "interpreter/graph_builder.hpp"

namespace kerf::eval {

// True when the subtree at `root` holds a Hull, Minkowski or Resize node.
bool has_geometry_ops(const graph::SceneGraph& g, std::uint32_t root);

// The subtree at `root` as a graph whose root it is, with the matrices,
// materials, meshes and polygons it uses (each copied once); no ghosts and
// no scene statements.
graph::SceneGraph extract_subtree(const graph::SceneGraph& g, std::uint32_t root);

// `sub` appended to the builder's graph, its table indices shifted; the id
// of its root there.
std::uint32_t append_graph(GraphBuilder& g, graph::SceneGraph&& sub);

}  // namespace kerf::eval
