// Builds the SceneGraph arena while statements evaluate. Every statement
// pushes the ids of the nodes it produced onto one shared `pending` stack;
// a parent remembers the stack height when it starts and, when its children
// are done, moves that run into child_refs in one go. So nodes come before
// their parents and no node owns a heap-allocated child list.
#pragma once
#include <new>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "csg/huge_pages.hpp"
#include "csg/populate_ahead.hpp"
#include "grammar/source.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

class GraphBuilder {
public:
    graph::SceneGraph graph;
    std::vector<std::uint32_t> pending;

    std::size_t mark() const { return pending.size(); }
    std::size_t produced_since(std::size_t mark) const { return pending.size() - mark; }

    // Large scenes: once an array passes 16K entries it is reserved at the
    // size the primitive limit allows (address space only; pages are touched
    // as nodes arrive), so a million-primitive loop never copies the arena
    // while it grows (docs/performance.md, "The front end"), and a second
    // thread faults its pages in a few MB ahead of its end (populate_ahead).
    std::size_t max_nodes = 0, max_matrices = 0;
    csg::PopulateAhead populate_ahead;
    csg::PopulateAhead::Watch nodes_ahead, refs_ahead, slots_ahead, offsets_ahead;

    // Makes room for n more elements of v. When they do not fit, v moves:
    // the page thread is stopped first if it watches v, since it must never
    // touch the block v leaves (an array outgrows its reservation only past
    // the primitive limit's cap, or below 16K entries, before it is watched).
    template <class T>
    void room(std::vector<T>& v, std::size_t n, std::size_t max, csg::PopulateAhead::Watch& watch) {
        if (v.size() + n <= v.capacity()) return;
        if (watch.slot >= 0) populate_ahead.stop();
        if (reserve_cap(v, n, max)) populate_ahead.watch(watch, v);
    }
    void room(graph::Transforms& t, std::size_t max) {
        const std::vector<std::uint32_t>& slots = t.slot_array();
        const std::vector<glm::dvec3>& offsets = t.offset_array();
        if (slots.size() < slots.capacity() && offsets.size() < offsets.capacity()) return;
        if (slots_ahead.slot >= 0 || offsets_ahead.slot >= 0) populate_ahead.stop();
        if (reserve_cap(t, 1, max)) {
            populate_ahead.watch(slots_ahead, t.slot_array());
            populate_ahead.watch(offsets_ahead, t.offset_array());
        }
    }
    // v reserved at max when it has 16K entries and the cap is larger; false
    // when not. The whole reservation counts against RLIMIT_DATA (the memory
    // cap): refused, the array grows as any vector does and only a scene
    // that really needs the memory runs out of it.
    template <class V>
    static bool reserve_cap(V& v, std::size_t n, std::size_t max) {
        if (v.size() < 16384 || v.size() + n > max) return false;
        try {
            reserve_huge(v, max);
        } catch (const std::bad_alloc&) {
            return false;
        }
        return true;
    }
    template <class T>
    static void reserve_huge(std::vector<T>& v, std::size_t n) { csg::reserve_huge(v, n); }
    static void reserve_huge(graph::Transforms& t, std::size_t n) { t.reserve_huge(n); }

    // Every push to the node, child and transform arrays goes through the
    // builder (room() before it, advance() after), so none moves one under
    // the page thread.
    void add_matrix(const glm::dmat4& m) {
        room(graph.matrices, max_matrices);
        graph.matrices.push_back(m);
        populate_ahead.advance(slots_ahead, graph.matrices.slot_array());
        populate_ahead.advance(offsets_ahead, graph.matrices.offset_array());
    }
    // Replaces transform i (linear_extrude's taper): a general matrix may
    // become a translation, whose offset is appended to a watched array.
    void set_matrix(std::size_t i, const glm::dmat4& m) {
        const std::vector<glm::dvec3>& offsets = graph.matrices.offset_array();
        if (offsets.size() == offsets.capacity() && offsets_ahead.slot >= 0) populate_ahead.stop();
        graph.matrices.set(i, m);
        populate_ahead.advance(offsets_ahead, graph.matrices.offset_array());
    }
    void add_child_refs(const std::uint32_t* first, std::size_t n) {
        room(graph.child_refs, n, max_nodes, refs_ahead);
        if (n == 1) graph.child_refs.push_back(*first);  // a transform's one child: no range insert
        else graph.child_refs.insert(graph.child_refs.end(), first, first + n);
        populate_ahead.advance(refs_ahead, graph.child_refs);
    }

    // The OpenSCAD dialect's mixing rule (docs/spec.md §10): set, a child of
    // the other kind than an operation's first is left out with this warning
    // instead of the error, as OpenSCAD 2021.01 ignores it.
    std::function<void(const SourceLoc&, const std::string&)> warn_mixed;

    std::uint32_t add(graph::Node&& n) {
        room(graph.nodes, 1, max_nodes, nodes_ahead);
        graph.nodes.push_back(std::move(n));
        populate_ahead.advance(nodes_ahead, graph.nodes);
        return static_cast<std::uint32_t>(graph.nodes.size() - 1);
    }
    void push(std::uint32_t id) { pending.push_back(id); }

    // One node of `kind` whose children are pending[mark..]; replaces them.
    // It is 2D when its first child is; a child of the other kind is an
    // error at it (docs/spec.md §10), or dropped by warn_mixed.
    std::uint32_t make_node(std::size_t mark, graph::NodeKind kind, const SourceLoc& loc, std::uint32_t index = 0) {
        bool flat = false;
        if (pending.size() > mark) {
            flat = graph.nodes[pending[mark]].flat;
            if (pending.size() > mark + 1) drop_mixed(mark, flat);
        }
        const auto first_child = static_cast<std::uint32_t>(graph.child_refs.size());
        const auto child_count = static_cast<std::uint32_t>(pending.size() - mark);
        add_child_refs(pending.data() + mark, child_count);
        pending.resize(mark);
        graph::Node& n = emplace(loc);
        n.kind = kind;
        n.index = index;
        n.flat = flat;
        n.first_child = first_child;
        n.child_count = child_count;
        const auto id = static_cast<std::uint32_t>(graph.nodes.size() - 1);
        pending.push_back(id);
        return id;
    }

    // A new node at loc, its other fields the defaults, built in place (not
    // built aside and moved in: 88 bytes each, a loop of a million leaves).
    graph::Node& emplace(const SourceLoc& loc) {
        if (graph.nodes.size() == graph.nodes.capacity()) {  // the arena moves: loc may be a node's, so copied first
            graph::Node n;
            n.loc = loc;
            room(graph.nodes, 1, max_nodes, nodes_ahead);
            graph::Node& moved = graph.nodes.emplace_back(std::move(n));
            populate_ahead.advance(nodes_ahead, graph.nodes);
            return moved;
        }
        graph::Node& n = graph.nodes.emplace_back();
        populate_ahead.advance(nodes_ahead, graph.nodes);
        n.loc = loc;
        return n;
    }

    // Children pending[mark + 1..] of the other kind than the first (flat
    // or not): an error at the first such (docs/spec.md §10), or dropped by
    // warn_mixed.
    void drop_mixed(std::size_t mark, bool flat) {
        std::size_t kept = mark + 1;
        for (std::size_t i = mark + 1; i < pending.size(); ++i) {
            const graph::Node& c = graph.nodes[pending[i]];
            if (c.flat == flat) {
                pending[kept++] = pending[i];
                continue;
            }
            if (!warn_mixed)
                throw SourceError(c.loc, c.flat ? "a 2D shape cannot be combined with 3D solids in one operation"
                                                : "a 3D solid cannot be combined with 2D shapes in one operation");
            warn_mixed(c.loc, c.flat ? "mixing 2D and 3D objects is not supported: this 2D shape is ignored"
                                     : "mixing 2D and 3D objects is not supported: this 3D solid is ignored");
        }
        pending.resize(kept);
    }

    // What a statement that groups its children contributes (a module call,
    // a for loop, an if): nothing for no solid, the solid itself for one,
    // their union for several.
    void group(std::size_t mark, const SourceLoc& loc) {
        if (pending.size() - mark > 1) make_node(mark, graph::NodeKind::Union, loc);
    }

    // True when pending[mark..] (a block's result) is 2D.
    bool flat_since(std::size_t mark) const { return pending.size() > mark && graph.nodes[pending[mark]].flat; }

    // The 2D shapes pending[mark..] extruded to z0 < z < z1: the unit slab
    // they are carried on, mapped in z (scene_graph.hpp, Node::flat).
    void extrude(std::size_t mark, double z0, double z1, const SourceLoc& loc) {
        glm::dmat4 m(1.0);
        m[2][2] = z1 - z0;
        m[3][2] = z0;
        extrude(mark, m, loc);
    }

    // The same with the unit slab mapped by m (linear_extrude's v: a shear).
    void extrude(std::size_t mark, const glm::dmat4& m, const SourceLoc& loc) {
        if (pending.size() == mark) return;
        group(mark, loc);
        add_matrix(m);
        make_node(mark, graph::NodeKind::Transform, loc, static_cast<std::uint32_t>(graph.matrices.size() - 1));
        graph.nodes[pending.back()].flat = false;
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
