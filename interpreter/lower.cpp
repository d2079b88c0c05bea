// lower_to_csg: one iterative post-order walk of the scene graph builds a
// temporary flattened tree (TreeBuilder), then one pre-order walk writes it
// into csg::Scene (emit). Both walks use explicit stacks, so a lopsided
// chain of a million unions cannot overflow the call stack, and child lists
// are linked lists so merging a nested union into its parent is O(1).
#include "interpreter/lower.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "interpreter/huge_pages.hpp"
#include "interpreter/leaf_placement.hpp"
#include "interpreter/mesh_lowering.hpp"
#include "interpreter/primitive_bounds.hpp"
#include "interpreter/scene_defaults.hpp"

namespace kerf {

namespace {

using csg::Aabb;
using csg::kNone;
using scene::NodeKind;

// A node of the flattened tree under construction. Children form a singly
// linked list through `next` (for a Difference the first one is the minuend).
struct TNode {
    csg::Op op = csg::Op::Leaf;
    std::uint32_t leaf = kNone;
    std::uint32_t head = kNone, tail = kNone, count = 0;
    std::uint32_t next = kNone;
    Aabb bounds;
};

// One scene-graph node being lowered: its context (transform and material
// scope for its children) and the operands gathered so far.
struct Frame {
    std::uint32_t gnode = 0;
    NodeKind kind = NodeKind::Union;
    std::uint32_t next_child = 0;
    csg::Affine xf;                     // world_from_object for the children
    std::uint32_t material = kNone;     // graph material index, kNone = default
    bool empty = false;                 // already known to be the empty solid
    std::uint32_t head = kNone, tail = kNone, count = 0;  // operands / subtrahends
    std::uint32_t minuend = kNone;
    Aabb bounds;                        // union: running box; difference: minuend's box
};

csg::Affine compose(const csg::Affine& parent, const glm::dmat4& child) {
    const glm::dmat3 l(child);
    const glm::dvec3 t(child[3]);
    return {parent.linear * l, parent.linear * t + parent.offset};
}

class TreeBuilder {
public:
    // Leaves are written straight into the scene's vector (in creation order;
    // the emitter compacts away the pruned ones in place) so the largest
    // array of the scene is touched once.
    TreeBuilder(const scene::SceneGraph& g, std::vector<csg::Leaf>& leaves) : leaves(leaves), g_(g) {
        std::size_t prims = 0;
        for (const scene::Node& n : g.nodes) prims += n.kind == NodeKind::Primitive;
        reserve_huge(leaves, prims);
        reserve_huge(nodes, g.nodes.size());
    }

    std::vector<TNode> nodes;
    std::vector<csg::Leaf>& leaves;  // material/mesh/source hold graph indices until emit

    // Returns the root TNode, or kNone for the empty solid.
    std::uint32_t build() {
        if (g_.root >= g_.nodes.size()) return kNone;
        if (g_.nodes[g_.root].kind == NodeKind::Primitive) return make_leaf(g_.root, {}, kNone);
        std::vector<Frame> stack;
        stack.push_back(open(g_.root, {}, kNone));
        for (;;) {
            Frame& f = stack.back();
            const scene::Node& gn = g_.nodes[f.gnode];
            if (f.next_child < gn.child_count) {
                const std::uint32_t c = child(gn, f.gnode, f.next_child++);
                if (g_.nodes[c].kind == NodeKind::Primitive) {
                    deliver(f, make_leaf(c, f.xf, f.material));
                } else {
                    Frame next = open(c, f.xf, f.material);
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
    const scene::SceneGraph& g_;

    std::uint32_t child(const scene::Node& gn, std::uint32_t parent, std::uint32_t i) const {
        const std::size_t ref = std::size_t(gn.first_child) + i;
        // Children precede parents in the arena: checking it rules out cycles.
        if (ref >= g_.child_refs.size() || g_.child_refs[ref] >= parent)
            throw std::invalid_argument("lower_to_csg: malformed scene graph (bad child reference)");
        return g_.child_refs[ref];
    }

    Frame open(std::uint32_t gnode, const csg::Affine& xf, std::uint32_t material) const {
        const scene::Node& gn = g_.nodes[gnode];
        Frame f;
        f.gnode = gnode;
        f.kind = gn.kind;
        f.xf = xf;
        f.material = material;
        if (gn.kind == NodeKind::Transform) {
            if (gn.index >= g_.matrices.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad matrix index)");
            f.xf = compose(xf, g_.matrices[gn.index]);
        } else if (gn.kind == NodeKind::Appearance) {
            if (gn.index >= g_.materials.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad material index)");
            f.material = gn.index;  // the innermost scope wins
        }
        return f;
    }

    std::uint32_t make_leaf(std::uint32_t gnode, const csg::Affine& xf, std::uint32_t material) {
        const scene::Node& gn = g_.nodes[gnode];
        csg::Leaf& leaf = leaves.emplace_back();
        leaf.kind = static_cast<csg::PrimKind>(gn.prim);
        for (int i = 0; i < 6; ++i) leaf.p[i] = gn.p[i];
        leaf.material = material;
        leaf.source = gnode;
        const std::vector<glm::dvec3>* points = nullptr;
        if (gn.prim == scene::PrimKind::Mesh) {
            if (gn.index >= g_.meshes.size())
                throw std::invalid_argument("lower_to_csg: malformed scene graph (bad mesh index)");
            leaf.mesh = gn.index;
            points = &g_.meshes[gn.index].points;
        }
        place_leaf(leaf, xf, points, gn.loc);
        if (leaf.bounds.empty()) {  // e.g. a mesh without points
            leaves.pop_back();
            return kNone;
        }
        TNode t;
        t.op = csg::Op::Leaf;
        t.leaf = static_cast<std::uint32_t>(leaves.size() - 1);
        t.bounds = leaf.bounds;
        nodes.push_back(t);
        return static_cast<std::uint32_t>(nodes.size() - 1);
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

    bool is_plane(std::uint32_t n) const {
        return nodes[n].op == csg::Op::Leaf && leaves[nodes[n].leaf].kind == csg::PrimKind::Plane;
    }

    void add_subtrahend(Frame& f, std::uint32_t n) {
        // A subtrahend whose box misses the minuend's cannot remove anything;
        // nor can a (tilted, so unbounded-box) half-space missing that box.
        if (Aabb::overlap(nodes[n].bounds, f.bounds).empty()) return;
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
                    f.bounds = nodes[r].bounds;
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
                if (nodes[r].op == csg::Op::Union) splice(f, nodes[r]); else append(f, r);
                f.bounds.extend(nodes[r].bounds);
                return;
        }
    }

    std::uint32_t make_op(csg::Op op, std::uint32_t head, std::uint32_t tail, std::uint32_t count,
                          const Aabb& bounds) {
        TNode t;
        t.op = op;
        t.head = head;
        t.tail = tail;
        t.count = count;
        t.bounds = bounds;
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
                if (f.count == 0) return kNone;
                if (f.count == 1) return single(f.head);
                return make_op(csg::Op::Union, f.head, f.tail, f.count, f.bounds);
        }
    }

    std::uint32_t finish_intersection(Frame& f) {
        if (f.empty || f.count == 0) return kNone;
        Aabb box = Aabb::everything();
        for (std::uint32_t c = f.head; c != kNone; c = nodes[c].next) box = Aabb::overlap(box, nodes[c].bounds);
        for (std::uint32_t c = f.head; c != kNone && !box.empty(); c = nodes[c].next)
            if (is_plane(c)) box = clip_by_halfspace(box, world_halfspace(leaves[nodes[c].leaf]));
        if (box.empty()) return kNone;
        drop_redundant_halfspaces(f, box);
        if (f.count == 1) return single(f.head);
        if (!trim_union_operands(f, box)) return kNone;
        return make_op(csg::Op::Intersection, f.head, f.tail, f.count, box);
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
                if (!Aabb::overlap(nodes[m].bounds, box).empty()) {
                    nodes[m].next = kNone;
                    if (head == kNone) head = m; else nodes[tail].next = m;
                    tail = m;
                    ++count;
                    ubox.extend(nodes[m].bounds);
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
                u.bounds = ubox;
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
        if (f.count == 0) return single(f.minuend);
        nodes[f.minuend].next = f.head;
        return make_op(csg::Op::Difference, f.minuend, f.tail, f.count + 1, f.bounds);
    }
};

// Writes the flattened tree into the scene in pre-order, remapping leaves,
// materials, meshes and sources to only those the surviving leaves use.
class Emitter {
public:
    Emitter(const scene::SceneGraph& g, TreeBuilder& t, csg::Scene& s) : g_(g), t_(t), s_(s) {}

    void emit(std::uint32_t root) {
        s_.materials.push_back(csg::Material{});  // 0: the default light grey
        material_map_.assign(g_.materials.size(), kNone);
        mesh_map_.assign(g_.meshes.size(), kNone);
        if (root != kNone) {
            reserve_huge(s_.nodes, t_.nodes.size());
            reserve_huge(s_.children, t_.nodes.size());
            emit_tree(root);
        }
        keep_emitted_leaves();
    }

private:
    // Leaf i of the scene is builder leaf order_[i].
    std::vector<std::uint32_t> order_;

    // Pre-order visits leaves in the order the builder created them (every
    // merge keeps operand order), so the survivors can be moved down in place.
    void keep_emitted_leaves() {
        std::vector<csg::Leaf>& leaves = s_.leaves;
        bool increasing = true;
        for (std::size_t k = 0; k < order_.size(); ++k) increasing = increasing && order_[k] >= k && (k == 0 || order_[k] > order_[k - 1]);
        if (increasing) {
            for (std::size_t k = 0; k < order_.size(); ++k)
                if (order_[k] != k) leaves[k] = leaves[order_[k]];
            leaves.resize(order_.size());
        } else {  // not expected; kept so a future merge rule cannot corrupt leaves
            std::vector<csg::Leaf> out;
            out.reserve(order_.size());
            for (std::uint32_t t : order_) out.push_back(leaves[t]);
            leaves = std::move(out);
        }
        for (csg::Leaf& leaf : leaves) resolve(leaf);
    }

    void emit_tree(std::uint32_t root) {
        s_.root = 0;
        struct Item { std::uint32_t tnode, parent, slot; };
        std::vector<Item> stack{{root, kNone, kNone}};
        std::vector<std::uint32_t> kids;
        while (!stack.empty()) {
            const Item it = stack.back();
            stack.pop_back();
            const TNode& tn = t_.nodes[it.tnode];
            const auto index = static_cast<std::uint32_t>(s_.nodes.size());
            csg::Node node;
            node.op = tn.op;
            node.parent = it.parent;
            node.bounds = tn.bounds;
            if (it.slot != kNone) s_.children[it.slot] = index;
            if (tn.op == csg::Op::Leaf) {
                node.first = static_cast<std::uint32_t>(order_.size());
                node.count = 0;
                order_.push_back(tn.leaf);
                s_.nodes.push_back(node);
                continue;
            }
            node.first = static_cast<std::uint32_t>(s_.children.size());
            node.count = tn.count;
            s_.nodes.push_back(node);
            s_.children.resize(s_.children.size() + tn.count, kNone);
            kids.clear();
            for (std::uint32_t c = tn.head; c != kNone; c = t_.nodes[c].next) kids.push_back(c);
            // Reverse push so the first child is emitted (and numbered) first.
            for (std::size_t k = kids.size(); k-- > 0;)
                stack.push_back({kids[k], index, node.first + static_cast<std::uint32_t>(k)});
        }
    }

    const scene::SceneGraph& g_;
    TreeBuilder& t_;
    csg::Scene& s_;
    std::vector<std::uint32_t> material_map_, mesh_map_;
    std::unordered_map<const SourceFile*, std::uint32_t> file_by_ptr_;
    std::unordered_map<std::string, std::uint32_t> file_by_path_;
    struct SourceKey {
        std::uint32_t file, line, col;
        bool operator==(const SourceKey&) const = default;
    };
    struct SourceHash {
        std::size_t operator()(const SourceKey& k) const {
            return std::hash<std::uint64_t>{}((std::uint64_t(k.file) << 40) ^ (std::uint64_t(k.line) << 16) ^ k.col);
        }
    };
    std::unordered_map<SourceKey, std::uint32_t, SourceHash> source_map_;
    const SourceFile* last_file_ = nullptr;
    std::uint32_t last_file_index_ = kNone;

    void resolve(csg::Leaf& leaf) {
        leaf.material = material(leaf.material);
        if (leaf.mesh != kNone) leaf.mesh = mesh(leaf.mesh);
        leaf.source = source(g_.nodes[leaf.source].loc);
    }

    std::uint32_t material(std::uint32_t gm) {
        if (gm == kNone) return 0;
        if (material_map_[gm] == kNone) {
            const scene::Material& m = g_.materials[gm];
            csg::Material c;
            c.color = m.color;
            c.alpha = m.alpha;
            c.interior = m.interior;
            c.diffuse = m.diffuse;
            c.specular = m.specular;
            c.shininess = m.shininess;
            c.reflect = m.reflect;
            material_map_[gm] = static_cast<std::uint32_t>(s_.materials.size());
            s_.materials.push_back(c);
        }
        return material_map_[gm];
    }

    std::uint32_t mesh(std::uint32_t gm) {
        if (mesh_map_[gm] == kNone) {  // converted once, shared by every leaf using it
            mesh_map_[gm] = static_cast<std::uint32_t>(s_.meshes.size());
            s_.meshes.push_back(lower_mesh(g_.meshes[gm]));
        }
        return mesh_map_[gm];
    }

    std::uint32_t file(const SourceFile* f) {
        if (f == last_file_) return last_file_index_;
        auto it = file_by_ptr_.find(f);
        std::uint32_t index;
        if (it != file_by_ptr_.end()) {
            index = it->second;
        } else {
            const std::string path = f ? f->path : std::string("<command line>");
            auto [pit, added] = file_by_path_.try_emplace(path, static_cast<std::uint32_t>(s_.files.size()));
            if (added) s_.files.push_back(path);
            index = pit->second;
            file_by_ptr_.emplace(f, index);
        }
        last_file_ = f;
        last_file_index_ = index;
        return index;
    }

    std::uint32_t source(const SourceLoc& loc) {
        if (!loc.file && loc.line == 0) return kNone;
        const SourceKey key{file(loc.file.get()), loc.line, loc.col};
        auto [it, added] = source_map_.try_emplace(key, static_cast<std::uint32_t>(s_.sources.size()));
        if (added) s_.sources.push_back({key.file, key.line, key.col});
        return it->second;
    }
};

void apply_scene_statements(const scene::SceneGraph& g, csg::Scene& s) {
    if (g.camera) {
        const scene::Camera& c = *g.camera;
        s.camera.position = c.position;
        s.camera.look_at = c.look_at;
        s.camera.up = c.up;
        s.camera.fov = c.fov;
        s.camera.orthographic = c.orthographic;
        s.camera.height = c.height;
    } else {
        s.camera = default_camera(framing_box(s));
    }
    if (g.lights.empty()) {
        s.lights = default_lights(s.camera);
    } else {
        for (const scene::Light& l : g.lights) {
            csg::Light c;
            c.directional = l.directional;
            c.position = l.position;
            c.direction = l.direction;
            c.color = l.color;
            c.intensity = l.intensity;
            s.lights.push_back(c);
        }
    }
    s.background = g.background.value_or(glm::dvec3(0.2, 0.2, 0.2));
}

}  // namespace

csg::Scene lower_to_csg(const scene::SceneGraph& graph) {
    csg::Scene scene;
    TreeBuilder builder(graph, scene.leaves);
    const std::uint32_t root = builder.build();
    Emitter(graph, builder, scene).emit(root);
    apply_scene_statements(graph, scene);
    return scene;
}

}  // namespace kerf
