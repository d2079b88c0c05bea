// Builds the SceneGraph arena while statements evaluate. Every statement
// pushes the ids of the nodes it produced onto one shared `pending` stack;
// a parent remembers the stack height when it starts and, when its children
// are done, moves that run into child_refs in one go. So nodes come before
// their parents and no node owns a heap-allocated child list.
#pragma once
#include <cstdint>
#include <vector>

#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

class GraphBuilder {
public:
    graph::SceneGraph graph;
    std::vector<std::uint32_t> pending;

    std::size_t mark() const { return pending.size(); }
    std::size_t produced_since(std::size_t mark) const { return pending.size() - mark; }

    // Large scenes: once an array passes 64K entries it is reserved at the
    // size the primitive limit allows (address space only; pages are touched
    // as nodes arrive), so a million-primitive loop never copies the arena
    // while it grows.
    std::size_t max_nodes = 0, max_matrices = 0;
    template <class V>
    static void grow(V& v, std::size_t max) {
        if (v.size() == v.capacity() && v.size() >= 65536 && max > v.capacity()) v.reserve(max);
    }
    void add_matrix(const glm::dmat4& m) {
        grow(graph.matrices, max_matrices);
        graph.matrices.push_back(m);
    }

    std::uint32_t add(graph::Node&& n) {
        grow(graph.nodes, max_nodes);
        graph.nodes.push_back(std::move(n));
        return static_cast<std::uint32_t>(graph.nodes.size() - 1);
    }
    void push(std::uint32_t id) { pending.push_back(id); }

    // One node of `kind` whose children are pending[mark..]; replaces them.
    std::uint32_t make_node(std::size_t mark, graph::NodeKind kind, const SourceLoc& loc, std::uint32_t index = 0) {
        graph::Node n;
        n.kind = kind;
        n.index = index;
        n.first_child = static_cast<std::uint32_t>(graph.child_refs.size());
        n.child_count = static_cast<std::uint32_t>(pending.size() - mark);
        n.loc = loc;
        grow(graph.child_refs, max_nodes);
        graph.child_refs.insert(graph.child_refs.end(), pending.begin() + static_cast<std::ptrdiff_t>(mark),
                                pending.end());
        pending.resize(mark);
        std::uint32_t id = add(std::move(n));
        pending.push_back(id);
        return id;
    }

    // What a statement that groups its children contributes (a module call,
    // a for loop, an if): nothing for no solid, the solid itself for one,
    // their union for several.
    void group(std::size_t mark, const SourceLoc& loc) {
        if (pending.size() - mark > 1) make_node(mark, graph::NodeKind::Union, loc);
    }

    // A transform or appearance over pending[mark..] (grouped first); nothing
    // when the block produced no solid.
    void wrap(std::size_t mark, graph::NodeKind kind, std::uint32_t index, const SourceLoc& loc) {
        if (pending.size() == mark) return;
        group(mark, loc);
        make_node(mark, kind, loc, index);
    }
};

}  // namespace kerf::eval
