// build_flat_tree: one post-order walk over the scene graph with an explicit
// stack of frames. Each frame gathers its operands as it goes (merging
// nested unions/intersections/subtrahend unions by list splicing, dropping
// what its box rules out), and turns them into one flat node when done.
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "lower/flat_tree.hpp"
#include "csg/huge_pages.hpp"
#include "lower/duplicate_leaves.hpp"
#include "lower/leaf_placement.hpp"
#include "lower/material_frames.hpp"
#include "lower/parallel_indices.hpp"
#include "lower/primitive_bounds.hpp"

namespace kerf::lowering {

namespace {

using csg::Aabb;
using csg::kNone;
using graph::NodeKind;

// One scene-graph node being lowered: its context (transform and material
// scope for its children) and the operands gathered so far.
struct Frame {
    std::uint32_t gnode = 0;
    NodeKind kind = NodeKind::Union;
    std::uint32_t next_child = 0;
    csg::Affine xf;                     // world_from_object for the children
    bool plain = true;                  // xf.linear finite and without -0: times the identity, itself (plain_linear)
    std::uint32_t material = kNone;     // graph material index, kNone = default
    csg::Affine material_xf;            // world_from_object at that material's call (its pattern space)
    bool empty = false;                 // already known to be the empty solid
    std::uint32_t head = kNone, tail = kNone, count = 0;  // operands / subtrahends
    // Union-like: the list is one child union's, spliced whole into an empty
    // list (a `for` under `union()` under `material()`): its leaves were made
    // distinct when that union finished, so finishing this one need not
    // look again (a pass over 10^5 leaves per level of nesting).
    bool distinct = false;
    std::uint32_t minuend = kNone;
    Aabb bounds;                        // union: running box; difference: minuend's box
    std::uint32_t scan_from = 0;        // children before this one are known not to start a parallel run
};

// A run of at least this many leaf-making children is placed by several
// threads (TreeBuilder::place_run): it starts threads three times (two
// page populations and the fill), ~60 us each, against ~0.15 us a leaf the
// second thread takes over, so the break-even is near 1,200 leaves; 2,048
// keeps a margin for a loaded machine.
constexpr std::uint32_t kParallelRun = 2048;
constexpr std::size_t kLeafChunk = 256;  // leaves a thread takes at a time: ~0.05 ms

csg::Affine compose(const csg::Affine& parent, const glm::dmat4& child) {
    const glm::dmat3 l(child);
    const glm::dvec3 t(child[3]);
    return {parent.linear * l, parent.linear * t + parent.offset};
}

// A matrix that the identity's product leaves bit for bit as it is: each
// entry is itself plus two products with 0, which are ±0 and change
// nothing but the sign of a -0 entry (and make NaN of an infinite one).
bool plain_linear(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r]) || (m[c][r] == 0 && std::signbit(m[c][r]))) return false;
    return true;
}

bool same_pattern_space(const csg::Material& a, const csg::Material& b) {
    return a.pattern == b.pattern && a.pattern_from_material.linear == b.pattern_from_material.linear &&
           a.pattern_from_material.offset == b.pattern_from_material.offset;
}

// FlatTree::locs while building: each distinct (file, line, col) once.
class LocTable {
public:
    std::vector<SourceLoc> locs;

    std::uint32_t index(const SourceLoc& loc) {
        const Key key{loc.file.get(), loc.line, loc.col};
        if (key == last_) return last_index_;  // siblings from one statement
        auto [it, added] = index_.try_emplace(key, static_cast<std::uint32_t>(locs.size()));
        if (added) locs.push_back(loc);
        last_ = key;
        last_index_ = it->second;
        return last_index_;
    }

private:
    struct Key {
        const SourceFile* file = nullptr;
        std::uint32_t line = 0, col = 0;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return std::hash<const void*>{}(k.file) ^ std::hash<std::uint64_t>{}((std::uint64_t(k.line) << 32) | k.col);
        }
    };
    std::unordered_map<Key, std::uint32_t, KeyHash> index_;
    Key last_{nullptr, ~0u, ~0u};
    std::uint32_t last_index_ = kNone;
};

class TreeBuilder {
public:
    // Leaves are written straight into the scene's vector (in creation order;
    // the emitter compacts away the pruned ones in place) so the largest
    // array of the scene is touched once.
    TreeBuilder(const graph::SceneGraph& g, std::vector<csg::Leaf>& out, std::uint32_t root, unsigned threads)
        : leaves(out), g_(g), root_(root), threads_(threads) {
        std::size_t prims = 0;
        for (const graph::Node& n : g.nodes) prims += n.kind == NodeKind::Primitive;
        csg::reserve_huge(out, prims);
        csg::reserve_huge(nodes, g.nodes.size());
    }

    std::vector<TNode> nodes;
    std::vector<Aabb> boxes;         // TNode::leaf of an operation points here
    std::vector<csg::Leaf>& leaves;  // material/mesh/source hold builder indices until emit
    MaterialFrames frames;           // the leaves' material_frame indices point here
    LocTable locs;                   // the leaves' source and the nodes' loc point here

    // Returns the root TNode, or kNone for the empty solid.
    std::uint32_t build() {
        if (root_ >= g_.nodes.size()) return kNone;
        if (g_.nodes[root_].kind == NodeKind::Primitive) return make_leaf(root_, Frame{});
        std::vector<Frame> stack;
        stack.push_back(open(root_, Frame{}));
        for (;;) {
            Frame& f = stack.back();
            const graph::Node& gn = g_.nodes[f.gnode];
            if (f.next_child < gn.child_count) {
                if (threads_ != 1 && f.next_child >= f.scan_from && gn.child_count - f.next_child >= kParallelRun &&
                    place_run(f, gn))
                    continue;
                const std::uint32_t c = child(gn, f.gnode, f.next_child++);
                if (g_.nodes[c].kind == NodeKind::Primitive) {
                    deliver(f, make_leaf(c, f));
                } else {
                    Frame next = open(c, f);
                    stack.push_back(std::move(next));
                }
                continue;
            }
            const std::uint32_t result = finish(f);
            stack.pop_back();
            if (stack.empty()) return result;
            deliver(stack.back(), result);
        }
    }

private:
    const graph::SceneGraph& g_;
    const std::uint32_t root_;
    const unsigned threads_;  // for wide unions' runs of leaves (place_run); 1: all serial

    // Child i of `parent` (node gn), or kNone for a bad reference. Children
    // precede parents in the arena: checking it rules out cycles.
    std::uint32_t child_or_none(const graph::Node& gn, std::uint32_t parent, std::uint32_t i) const {
        const std::size_t ref = std::size_t(gn.first_child) + i;
        if (ref >= g_.child_refs.size() || g_.child_refs[ref] >= parent) return kNone;
        return g_.child_refs[ref];
    }

    std::uint32_t child(const graph::Node& gn, std::uint32_t parent, std::uint32_t i) const {
        const std::uint32_t c = child_or_none(gn, parent, i);
        if (c == kNone) throw std::invalid_argument("lower_to_csg: malformed scene graph (bad child reference)");
        return c;
    }

    Frame open(std::uint32_t gnode, const Frame& parent) const {
        const graph::Node& gn = g_.nodes[gnode];
        Frame f;
        f.gnode = gnode;
        f.kind = gn.kind;
        f.xf = parent.xf;
        f.material = parent.material;
        f.material_xf = parent.material_xf;
        f.plain = parent.plain;
        const csg::Affine& xf = parent.xf;
        if (gn.kind == NodeKind::Transform) {
            if (gn.index >= g_.matrices.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad matrix index)");
            // A translation (a loop's translate() per leaf) under a plain
            // frame: compose's product of the linear parts is the frame's
            // own, so only the offset is computed, by compose's formula.
            const glm::dvec3* t = g_.matrices.translation_offset(gn.index);
            if (t && parent.plain) {
                f.xf.offset = xf.linear * *t + xf.offset;
            } else {
                f.xf = compose(xf, g_.matrices[gn.index]);
                f.plain = plain_linear(f.xf.linear);
            }
        } else if (gn.kind == NodeKind::Appearance) {
            if (gn.index >= g_.materials.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad material index)");
            // A pattern's space is that of the call that set it: an inner
            // color() keeping the pattern keeps its space too.
            const csg::Material& m = g_.materials[gn.index];
            if (parent.material == kNone || !same_pattern_space(g_.materials[parent.material], m)) f.material_xf = xf;
            f.material = gn.index;  // the innermost scope wins
        }
        return f;
    }

    // What make_leaf writes into a leaf from the graph alone (no builder
    // table): so the children of a wide union can be placed in parallel.
    void fill_leaf(csg::Leaf& leaf, std::uint32_t gnode, const csg::Affine& xf, std::uint32_t material) const {
        const graph::Node& gn = g_.nodes[gnode];
        leaf.kind = gn.prim;
        for (int i = 0; i < 6; ++i) leaf.p[i] = gn.p[i];
        leaf.material = material;
        const std::vector<glm::dvec3>* points = nullptr;
        if (gn.prim == csg::PrimKind::Mesh) {
            if (gn.index >= g_.meshes.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad mesh index)");
            leaf.mesh = gn.index;
            points = &g_.meshes[gn.index].points;
        }
        std::vector<glm::dvec3> corners;
        const csg::Polygon2* section = nullptr;
        if (gn.prim == csg::PrimKind::Prism || gn.prim == csg::PrimKind::Lathe) {
            if (gn.index >= g_.polygons.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad polygon index)");
            leaf.polygon = gn.index;
            section = &g_.polygons[gn.index];
            if (gn.prim == csg::PrimKind::Prism) {
                corners = prism_corners(*section, gn.p);
                points = &corners;
            }
        }
        place_leaf(leaf, xf, points, gn.loc, section);
    }

    std::uint32_t make_leaf(std::uint32_t gnode, const Frame& parent) {
        const std::uint32_t material = parent.material;
        csg::Leaf& leaf = leaves.emplace_back();
        leaf.source = locs.index(g_.nodes[gnode].loc);
        fill_leaf(leaf, gnode, parent.xf, material);
        // Only a patterned material reads its call's space; the inverse is
        // regular because the leaf's own transform (which it is a factor of) is.
        if (material != kNone && g_.materials[material].pattern != csg::Pattern::None)
            leaf.material_frame = frames.frame_of_call(parent.material_xf);
        if (leaf.bounds.empty()) {  // e.g. a mesh without points
            leaves.pop_back();
            return kNone;
        }
        TNode t;
        t.op = csg::Op::Leaf;
        t.leaf = static_cast<std::uint32_t>(leaves.size() - 1);
        t.loc = leaf.source;
        t.hash = leaf_hash(leaf);
        nodes.push_back(t);
        return static_cast<std::uint32_t>(nodes.size() - 1);
    }

    // The primitive child i of `parent` stands for when it is a primitive or
    // a transform of one alone (a loop's `translate(...) sphere(...)`), else
    // kNone. Checks what child() and open() would throw for, without
    // throwing: such a child ends a run and the serial walk reports it in order.
    std::uint32_t run_leaf(std::uint32_t parent, const graph::Node& gn, std::uint32_t i) const {
        const std::uint32_t c = child_or_none(gn, parent, i);
        if (c == kNone) return kNone;
        const graph::Node& cn = g_.nodes[c];
        if (cn.kind == NodeKind::Primitive) return c;
        if (cn.kind != NodeKind::Transform || cn.child_count != 1 || cn.index >= g_.matrices.size()) return kNone;
        const std::uint32_t p = child_or_none(cn, c, 0);
        return p != kNone && g_.nodes[p].kind == NodeKind::Primitive ? p : kNone;
    }

    // A union-like frame's next children when at least kParallelRun of them
    // in a row are leaves (run_leaf): their leaves and nodes are placed by
    // several threads into slots sized first, then delivered in order on
    // this one, with the serial walk's tables (locs) and pruning, so the
    // tree is the serial walk's bit for bit. False when there is no such
    // run here (the children up to its end are not looked at again).
    bool place_run(Frame& f, const graph::Node& gn) {
        const bool unionlike = f.kind != NodeKind::Intersection && f.kind != NodeKind::Difference;
        // A pattern's frame table is filled leaf by leaf (make_leaf): left serial.
        const bool patterned = f.material != kNone && g_.materials[f.material].pattern != csg::Pattern::None;
        std::uint32_t end = f.next_child;
        if (unionlike && !patterned)
            while (end < gn.child_count && run_leaf(f.gnode, gn, end) != kNone) ++end;
        const std::uint32_t run = end - f.next_child;
        if (run < kParallelRun) {
            f.scan_from = end + 1;
            return false;
        }
        const std::uint32_t first = f.next_child;
        const std::size_t leaf0 = leaves.size(), node0 = nodes.size();
        leaves.reserve(leaf0 + run);
        nodes.reserve(node0 + run);
        // The run's slots are fresh memory (31 MB of leaves at 10^5): their
        // first touch, most of a serial run's time, is shared too.
        populate_in_parallel(leaves.data() + leaf0, run * sizeof(csg::Leaf), threads_);
        populate_in_parallel(nodes.data() + node0, run * sizeof(TNode), threads_);
        leaves.resize(leaf0 + run);
        nodes.resize(node0 + run);
        for_each_index(run, kLeafChunk, threads_, [&](std::size_t k) {
            const std::uint32_t c = g_.child_refs[std::size_t(gn.first_child) + first + k];
            const std::uint32_t prim = run_leaf(f.gnode, gn, first + std::uint32_t(k));
            csg::Leaf& leaf = leaves[leaf0 + k];
            if (c == prim) fill_leaf(leaf, prim, f.xf, f.material);
            else fill_leaf(leaf, prim, open(c, f).xf, f.material);
            TNode& t = nodes[node0 + k];
            t.op = csg::Op::Leaf;
            if (!leaf.bounds.empty()) t.hash = leaf_hash(leaf);  // (source is not hashed)
        });
        // In order, as make_leaf and deliver would: a leaf with an empty box
        // still takes its source's place in the table, then is dropped.
        std::size_t kept = 0;
        for (std::uint32_t k = 0; k < run; ++k) {
            const std::uint32_t prim = run_leaf(f.gnode, gn, first + k);
            csg::Leaf& leaf = leaves[leaf0 + k];
            leaf.source = locs.index(g_.nodes[prim].loc);
            if (leaf.bounds.empty()) continue;
            const std::size_t l = leaf0 + kept, n = node0 + kept;
            if (l != leaf0 + k) {
                leaves[l] = leaf;
                nodes[n] = nodes[node0 + k];
            }
            nodes[n].leaf = static_cast<std::uint32_t>(l);
            nodes[n].loc = leaves[l].source;
            deliver(f, static_cast<std::uint32_t>(n));
            ++kept;
        }
        leaves.resize(leaf0 + kept);
        nodes.resize(node0 + kept);
        f.next_child = end;
        return true;
    }

    void append(Frame& f, std::uint32_t n) {
        nodes[n].next = kNone;
        if (f.head == kNone) f.head = n; else nodes[f.tail].next = n;
        f.tail = n;
        ++f.count;
    }

    void splice(Frame& f, const TNode& t) {
        if (f.head == kNone) f.head = t.head; else nodes[f.tail].next = t.head;
        f.tail = t.tail;
        f.count += t.count;
    }

    const Aabb& bounds(std::uint32_t n) const { return box(nodes[n], leaves, boxes); }

    bool is_plane(std::uint32_t n) const {
        return nodes[n].op == csg::Op::Leaf && leaves[nodes[n].leaf].kind == csg::PrimKind::Plane;
    }

    void add_subtrahend(Frame& f, std::uint32_t n) {
        // A subtrahend whose box misses the minuend's cannot remove anything;
        // nor can a (tilted, so unbounded-box) half-space missing that box.
        if (Aabb::overlap(bounds(n), f.bounds).empty()) return;
        if (is_plane(n) && clip_by_halfspace(f.bounds, world_halfspace(leaves[nodes[n].leaf])).empty()) return;
        append(f, n);
    }

    void deliver(Frame& f, std::uint32_t r) {
        switch (f.kind) {
            case NodeKind::Intersection:
                if (r == kNone) f.empty = true;
                else if (nodes[r].op == csg::Op::Intersection) splice(f, nodes[r]);
                else append(f, r);
                return;
            case NodeKind::Difference:
                if (f.next_child == 1) {
                    if (r == kNone) { f.empty = true; return; }
                    f.bounds = bounds(r);
                    if (nodes[r].op == csg::Op::Difference) {
                        // (a − b) − c = a − (b ∪ c): adopt the inner minuend and subtrahends.
                        const TNode& d = nodes[r];
                        f.minuend = d.head;
                        f.head = nodes[d.head].next;
                        f.tail = d.tail;
                        f.count = d.count - 1;
                        nodes[d.head].next = kNone;
                    } else {
                        f.minuend = r;
                    }
                    return;
                }
                if (r == kNone || f.empty) return;
                if (nodes[r].op == csg::Op::Union) {
                    for (std::uint32_t c = nodes[r].head; c != kNone;) {
                        const std::uint32_t next = nodes[c].next;
                        add_subtrahend(f, c);
                        c = next;
                    }
                } else {
                    add_subtrahend(f, r);
                }
                return;
            default:  // Union, Transform, Appearance: all unions of their children
                if (r == kNone) return;
                f.distinct = f.count == 0 && nodes[r].op == csg::Op::Union;
                if (nodes[r].op == csg::Op::Union) splice(f, nodes[r]); else append(f, r);
                f.bounds.extend(bounds(r));
                return;
        }
    }

    std::uint32_t make_op(const Frame& f, csg::Op op, std::uint32_t head, std::uint32_t tail,
                          std::uint32_t count, const Aabb& bounds) {
        TNode t;
        t.op = op;
        t.loc = locs.index(g_.nodes[f.gnode].loc);
        t.head = head;
        t.tail = tail;
        t.count = count;
        t.leaf = static_cast<std::uint32_t>(boxes.size());
        boxes.push_back(bounds);
        nodes.push_back(t);
        return static_cast<std::uint32_t>(nodes.size() - 1);
    }

    std::uint32_t single(std::uint32_t n) {
        nodes[n].next = kNone;
        return n;
    }

    std::uint32_t finish(Frame& f) {
        switch (f.kind) {
            case NodeKind::Intersection: return finish_intersection(f);
            case NodeKind::Difference: return finish_difference(f);
            default:
                if (!f.distinct) f.count = drop_duplicate_leaves(nodes, leaves, f.head, f.tail, f.count, threads_);
                if (f.count == 0) return kNone;
                if (f.count == 1) return single(f.head);
                return make_op(f, csg::Op::Union, f.head, f.tail, f.count, f.bounds);
        }
    }

    std::uint32_t finish_intersection(Frame& f) {
        if (f.empty || f.count == 0) return kNone;
        f.count = drop_duplicate_leaves(nodes, leaves, f.head, f.tail, f.count, threads_);
        Aabb box = Aabb::everything();
        for (std::uint32_t c = f.head; c != kNone; c = nodes[c].next) box = Aabb::overlap(box, bounds(c));
        for (std::uint32_t c = f.head; c != kNone && !box.empty(); c = nodes[c].next)
            if (is_plane(c)) box = clip_by_halfspace(box, world_halfspace(leaves[nodes[c].leaf]));
        if (box.empty()) return kNone;
        drop_redundant_halfspaces(f, box);
        if (f.count == 1) return single(f.head);
        if (!trim_union_operands(f, box)) return kNone;
        return make_op(f, csg::Op::Intersection, f.head, f.tail, f.count, box);
    }

    // A half-space containing the whole box of the intersection changes
    // nothing; drop it (keeping at least one operand).
    void drop_redundant_halfspaces(Frame& f, const Aabb& box) {
        std::uint32_t c = f.head;
        f.head = f.tail = kNone;
        const std::uint32_t total = f.count;
        f.count = 0;
        std::uint32_t dropped = 0;
        while (c != kNone) {
            const std::uint32_t next = nodes[c].next;
            bool redundant = false;
            if (is_plane(c) && dropped + 1 < total) {
                const HalfSpace h = world_halfspace(leaves[nodes[c].leaf]);
                redundant = clip_by_halfspace(box, {-h.normal, -h.offset}).empty();
            }
            if (redundant) ++dropped; else append(f, c);
            c = next;
        }
    }

    // Only the parts of a union operand inside the intersection's box can
    // matter: drop union members that miss it (and tighten the box with the
    // trimmed unions). Returns false when some operand has nothing left,
    // i.e. the intersection is empty.
    bool trim_union_operands(Frame& f, Aabb& box) {
        std::uint32_t c = f.head;
        f.head = f.tail = kNone;
        f.count = 0;
        while (c != kNone) {
            const std::uint32_t next = nodes[c].next;
            if (nodes[c].op != csg::Op::Union) {
                append(f, c);
                c = next;
                continue;
            }
            TNode& u = nodes[c];
            std::uint32_t head = kNone, tail = kNone, count = 0;
            Aabb ubox;
            for (std::uint32_t m = u.head; m != kNone;) {
                const std::uint32_t after = nodes[m].next;
                if (!Aabb::overlap(bounds(m), box).empty()) {
                    nodes[m].next = kNone;
                    if (head == kNone) head = m; else nodes[tail].next = m;
                    tail = m;
                    ++count;
                    ubox.extend(bounds(m));
                }
                m = after;
            }
            if (count == 0) return false;
            box = Aabb::overlap(box, ubox);
            if (count == 1 && nodes[head].op == csg::Op::Intersection) {
                splice(f, nodes[head]);  // keep intersections flat
            } else if (count == 1) {
                append(f, head);
            } else {
                u.head = head;
                u.tail = tail;
                u.count = count;
                boxes[u.leaf] = ubox;
                append(f, c);
            }
            c = next;
        }
        return !box.empty();
    }

    std::uint32_t finish_difference(Frame& f) {
        if (f.empty || f.minuend == kNone) return kNone;
        // Subtracting a half-space keeps only the minuend's part outside it.
        bool clipped = false;
        for (std::uint32_t c = f.head; c != kNone && !f.bounds.empty(); c = nodes[c].next) {
            if (!is_plane(c)) continue;
            HalfSpace h = world_halfspace(leaves[nodes[c].leaf]);
            f.bounds = clip_by_halfspace(f.bounds, {-h.normal, -h.offset});
            clipped = true;
        }
        if (f.bounds.empty()) return kNone;
        if (clipped) {  // the box shrank: drop subtrahends that now miss it
            std::uint32_t c = f.head;
            f.head = f.tail = kNone;
            f.count = 0;
            while (c != kNone) {
                const std::uint32_t next = nodes[c].next;
                add_subtrahend(f, c);
                c = next;
            }
        }
        f.count = drop_duplicate_leaves(nodes, leaves, f.head, f.tail, f.count, threads_);
        if (f.count == 0) return single(f.minuend);
        nodes[f.minuend].next = f.head;
        return make_op(f, csg::Op::Difference, f.minuend, f.tail, f.count + 1, f.bounds);
    }
};


}  // namespace

FlatTree build_flat_tree(const graph::SceneGraph& graph, std::vector<csg::Leaf>& leaves, std::uint32_t root,
                         unsigned threads) {
    TreeBuilder builder(graph, leaves, root == csg::kNone ? graph.root : root, threads);
    FlatTree tree;
    tree.root = builder.build();
    tree.nodes = std::move(builder.nodes);
    tree.boxes = std::move(builder.boxes);
    tree.material_frames = std::move(builder.frames.frames);
    tree.locs = std::move(builder.locs.locs);
    return tree;
}

}  // namespace kerf::lowering
