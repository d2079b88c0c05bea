// emit_flat_tree: the flat tree into csg::Scene arrays (pre-order, contiguous
// child runs), plus the tables only surviving leaves need: materials,
// material frames, meshes (converted once each), files and source locations.
#include <string>
#include <unordered_map>

#include "lower/flat_tree.hpp"
#include "csg/huge_pages.hpp"
#include "lower/mesh_lowering.hpp"
#include "lower/parallel_indices.hpp"

namespace kerf::lowering {

namespace {

using csg::kNone;

constexpr std::size_t kPopulateNodes = 16384;  // 1 MB of nodes: below, a thread's start costs what it saves

// Writes the flattened tree into the scene in pre-order, remapping leaves,
// materials, meshes and sources to only those the surviving leaves use.
class Emitter {
public:
    Emitter(const graph::SceneGraph& g, const FlatTree& t, csg::Scene& s, unsigned threads)
        : g_(g), t_(t), s_(s), threads_(threads) {}

    void emit(std::uint32_t root) {
        s_.materials.push_back(csg::Material{});  // 0: the default light grey
        material_map_.assign(g_.materials.size(), kNone);
        frame_map_.assign(t_.material_frames.size(), kNone);
        frame_map_[0] = 0;  // the identity: the scene's frame 0 too
        mesh_map_.assign(g_.meshes.size(), kNone);
        polygon_map_.assign(g_.polygons.size(), kNone);
        if (root != kNone) {
            csg::reserve_huge(s_.nodes, t_.nodes.size());
            csg::reserve_huge(s_.children, t_.nodes.size());
            // A big tree's node array (6 MB at 10^5 leaves) faulted in by
            // the threads first: the walk below fills it on one.
            if (threads_ != 1 && t_.nodes.size() >= kPopulateNodes)
                populate_in_parallel(s_.nodes.data(), t_.nodes.size() * sizeof(csg::Node), threads_);
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
        source_of_loc_.assign(t_.locs.size(), kUnresolved);
        if (increasing) {
            for (std::size_t k = 0; k < order_.size(); ++k) {
                if (order_[k] != k) leaves[k] = leaves[order_[k]];
                resolve(leaves[k]);
            }
            leaves.resize(order_.size());
        } else {  // not expected; kept so a future merge rule cannot corrupt leaves
            std::vector<csg::Leaf> out;
            out.reserve(order_.size());
            for (std::uint32_t t : order_) out.push_back(leaves[t]);
            leaves = std::move(out);
            for (csg::Leaf& leaf : leaves) resolve(leaf);
        }
    }

    // Pre-order by a stack of cursors into the child lists: a node's
    // children are numbered as they are reached, the first first, so a
    // union of 10^5 leaves is walked in place, not pushed as 10^5 items.
    void emit_tree(std::uint32_t root) {
        s_.root = 0;
        struct Cursor { std::uint32_t next, parent, slot, depth; };
        std::vector<Cursor> stack;
        const auto visit = [&](std::uint32_t t, std::uint32_t parent, std::uint32_t slot, std::uint32_t depth) {
            const TNode& tn = t_.nodes[t];
            if (depth > csg::kMaxDepth) too_deep(tn);
            const auto index = static_cast<std::uint32_t>(s_.nodes.size());
            csg::Node node;
            node.op = tn.op;
            node.parent = parent;
            node.bounds = box(tn, s_.leaves, t_.boxes);
            if (slot != kNone) s_.children[slot] = index;
            if (tn.op == csg::Op::Leaf) {
                node.first = static_cast<std::uint32_t>(order_.size());
                node.count = 0;
                order_.push_back(tn.leaf);
                s_.nodes.push_back(node);
                return;
            }
            node.first = static_cast<std::uint32_t>(s_.children.size());
            node.count = tn.count;
            s_.nodes.push_back(node);
            s_.children.resize(s_.children.size() + tn.count, kNone);
            stack.push_back({tn.head, index, node.first, depth + 1});
        };
        visit(root, kNone, kNone, 1);
        while (!stack.empty()) {
            Cursor& c = stack.back();
            if (c.next == kNone) {
                stack.pop_back();
                continue;
            }
            const std::uint32_t t = c.next;
            c.next = t_.nodes[t].next;
            const Cursor at = c;
            ++c.slot;
            visit(t, at.parent, at.slot, at.depth);  // may grow the stack: `c` is not used after
        }
    }

    // The tracer evaluates the tree recursively; csg::kMaxDepth is what its
    // stack is sized for (docs/lowering.md, "Depth").
    [[noreturn]] void too_deep(const TNode& tn) const {
        const std::string limit = std::to_string(csg::kMaxDepth);
        throw SourceError(t_.locs[tn.loc], "the CSG tree is deeper than " + limit +
                                                      " levels here (after unions and intersections are merged); "
                                                      "kerf renders trees up to " + limit + " levels deep");
    }

    const graph::SceneGraph& g_;
    const FlatTree& t_;
    csg::Scene& s_;
    const unsigned threads_;  // for populate_in_parallel; 1: none
    std::vector<std::uint32_t> material_map_, frame_map_, mesh_map_, polygon_map_;
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
        leaf.material_frame = frame(leaf.material_frame);
        if (leaf.mesh != kNone) leaf.mesh = mesh(leaf.mesh);
        if (leaf.polygon != kNone) leaf.polygon = polygon(leaf.polygon);
        // FlatTree::locs are distinct: one scene source per entry, found once.
        std::uint32_t& src = source_of_loc_[leaf.source];
        if (src == kUnresolved) src = source(t_.locs[leaf.source]);
        leaf.source = src;
    }
    static constexpr std::uint32_t kUnresolved = kNone - 1;
    std::vector<std::uint32_t> source_of_loc_;

    std::uint32_t material(std::uint32_t gm) {
        if (gm == kNone) return 0;
        if (material_map_[gm] == kNone) {
            material_map_[gm] = static_cast<std::uint32_t>(s_.materials.size());
            s_.materials.push_back(g_.materials[gm]);
        }
        return material_map_[gm];
    }

    std::uint32_t frame(std::uint32_t f) {  // only the frames surviving leaves use
        if (frame_map_[f] == kNone) {
            frame_map_[f] = static_cast<std::uint32_t>(s_.material_frames.size());
            s_.material_frames.push_back(t_.material_frames[f]);
        }
        return frame_map_[f];
    }

    std::uint32_t mesh(std::uint32_t gm) {
        if (mesh_map_[gm] == kNone) {  // converted once, shared by every leaf using it
            mesh_map_[gm] = static_cast<std::uint32_t>(s_.meshes.size());
            s_.meshes.push_back(lower_mesh(g_.meshes[gm]));
        }
        return mesh_map_[gm];
    }

    std::uint32_t polygon(std::uint32_t gp) {
        if (polygon_map_[gp] == kNone) {  // stored once, however many leaves extrude it
            polygon_map_[gp] = static_cast<std::uint32_t>(s_.polygons.size());
            s_.polygons.push_back(g_.polygons[gp]);
        }
        return polygon_map_[gp];
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


}  // namespace

void emit_flat_tree(const graph::SceneGraph& graph, const FlatTree& tree, csg::Scene& scene, unsigned threads) {
    Emitter(graph, tree, scene, threads).emit(tree.root);
}

}  // namespace kerf::lowering
