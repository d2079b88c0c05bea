// Lowering's intermediate form: the flattened, pruned operation
// tree as linked lists, built by one post-order walk of the scene graph
// (flat_tree.cpp) and written into csg::Scene by one pre-order walk
// (flat_tree_emit.cpp). Both walks use explicit stacks, so a lopsided chain
// of a million unions cannot overflow the call stack; child lists are linked
// lists so merging a nested union into its parent is O(1).
#pragma once
#include <cstdint>
#include <vector>

#include "interpreter/scene_graph.hpp"
#include "csg/scene.hpp"

namespace kerf::lowering {

// A node of the flattened tree. Children form a singly linked list through
// `next` (for a Difference the first one is the minuend).
// Its box is the leaf's own or, for an operation, one of FlatTree::boxes
// (box() below): a leaf's is not copied, which made the node 80 bytes
// instead of 32 (docs/performance.md, "Memory").
struct TNode {
    csg::Op op = csg::Op::Leaf;
    std::uint32_t leaf = csg::kNone;  // Leaf: index into the leaves vector; others: into FlatTree::boxes
    std::uint32_t head = csg::kNone, tail = csg::kNone, count = 0;
    std::uint32_t next = csg::kNone;
    std::uint32_t loc = csg::kNone;    // into FlatTree::locs: where the graph node it came from was written
    std::uint32_t hash = 0;            // Leaf: leaf_hash (duplicate_leaves.hpp)
};

// The box of `t`, clipped by its operation (docs/architecture.md).
inline const csg::Aabb& box(const TNode& t, const std::vector<csg::Leaf>& leaves, const std::vector<csg::Aabb>& boxes) {
    return t.op == csg::Op::Leaf ? leaves[t.leaf].bounds : boxes[t.leaf];
}

struct FlatTree {
    std::vector<TNode> nodes;
    std::vector<csg::Aabb> boxes;      // the operation nodes' boxes
    std::uint32_t root = csg::kNone;  // kNone: the empty solid
    std::vector<csg::Affine> material_frames;  // the leaves' material_frame table (0: identity)
    // The distinct source locations of the tree's nodes and leaves, so the
    // emitter needs no graph node: lowering can free the graph's node arrays
    // before it emits (docs/performance.md, "Memory").
    std::vector<SourceLoc> locs;
};

// Flattens and prunes the graph. Leaves are appended to `leaves` in creation
// order with their world matrices and boxes set, while material, mesh,
// material_frame (into FlatTree::material_frames) and source still hold the
// builder's indices (material kNone = default, source: into FlatTree::locs).
// Throws SourceError for singular transforms. `root`: the tree to flatten
// (kNone: graph.root; a ghost tree, csg/ghosts.hpp). `threads`: how many
// may place the leaves of a wide union (0: one per hardware thread); the
// tree is the same bits whatever the count.
FlatTree build_flat_tree(const graph::SceneGraph& graph, std::vector<csg::Leaf>& leaves,
                         std::uint32_t root = csg::kNone, unsigned threads = 1);

// Writes nodes/children in pre-order into `scene` (whose `leaves` are the
// ones build_flat_tree filled), keeps only the leaves the tree uses, and
// resolves materials, material frames, meshes and sources into the scene's
// tables. Reads only the graph's materials, meshes and polygons (its nodes
// may be gone). Throws SourceError at the first node deeper than csg::kMaxDepth.
// `threads`: how many may fault the node array in first (0: one per hardware thread).
void emit_flat_tree(const graph::SceneGraph& graph, const FlatTree& tree, csg::Scene& scene, unsigned threads = 1);

}  // namespace kerf::lowering
