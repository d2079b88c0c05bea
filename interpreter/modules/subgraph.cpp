#include "interpreter/modules/subgraph.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace kerf::eval {

namespace {

using NK = graph::NodeKind;
using P = csg::PrimKind;

// The ids reachable from `root`, ascending (children come before parents).
std::vector<std::uint32_t> reachable(const graph::SceneGraph& g, std::uint32_t root) {
    std::unordered_set<std::uint32_t> seen{root};  // not a flag per id: a projection in a long file
    std::vector<std::uint32_t> todo{root}, out;
    while (!todo.empty()) {
        const graph::Node& n = g.nodes[todo.back()];
        out.push_back(todo.back());
        todo.pop_back();
        for (std::uint32_t k = 0; k < n.child_count; ++k) {
            const std::uint32_t c = g.child_refs[n.first_child + k];
            if (seen.insert(c).second) todo.push_back(c);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

bool has_geometry_ops(const graph::SceneGraph& g, std::uint32_t root) {
    for (std::uint32_t id : reachable(g, root)) {
        const NK k = g.nodes[id].kind;
        if (k == NK::Hull || k == NK::Minkowski || k == NK::Resize) return true;
    }
    return false;
}

graph::SceneGraph extract_subtree(const graph::SceneGraph& g, std::uint32_t root) {
    graph::SceneGraph out;
    std::unordered_map<std::uint32_t, std::uint32_t> ids, materials, meshes, polygons;
    for (std::uint32_t id : reachable(g, root)) {
        graph::Node n = g.nodes[id];
        const std::uint32_t first = std::uint32_t(out.child_refs.size());
        for (std::uint32_t k = 0; k < n.child_count; ++k) out.child_refs.push_back(ids.at(g.child_refs[n.first_child + k]));
        n.first_child = first;
        if (n.kind == NK::Transform) {
            out.matrices.push_back(g.matrices[n.index]);
            n.index = std::uint32_t(out.matrices.size() - 1);
        } else if (n.kind == NK::Appearance) {
            auto [it, fresh] = materials.try_emplace(n.index, std::uint32_t(out.materials.size()));
            if (fresh) out.materials.push_back(g.materials[n.index]);
            n.index = it->second;
        } else if (n.kind == NK::Primitive && n.prim == P::Mesh) {
            auto [it, fresh] = meshes.try_emplace(n.index, std::uint32_t(out.meshes.size()));
            if (fresh) out.meshes.push_back(g.meshes[n.index]);
            n.index = it->second;
        } else if (n.kind == NK::Primitive && (n.prim == P::Prism || n.prim == P::Lathe)) {
            auto [it, fresh] = polygons.try_emplace(n.index, std::uint32_t(out.polygons.size()));
            if (fresh) out.polygons.push_back(g.polygons[n.index]);
            n.index = it->second;
        }
        out.nodes.push_back(std::move(n));
        ids[id] = std::uint32_t(out.nodes.size() - 1);
    }
    out.root = ids.at(root);
    return out;
}

std::uint32_t append_graph(GraphBuilder& g, graph::SceneGraph&& sub) {
    graph::SceneGraph& d = g.graph;
    const auto nodes = std::uint32_t(d.nodes.size()), refs = std::uint32_t(d.child_refs.size()),
               matrices = std::uint32_t(d.matrices.size()), materials = std::uint32_t(d.materials.size()),
               meshes = std::uint32_t(d.meshes.size()), polygons = std::uint32_t(d.polygons.size());
    for (std::size_t i = 0; i < sub.matrices.size(); ++i) g.add_matrix(sub.matrices[i]);
    d.materials.insert(d.materials.end(), sub.materials.begin(), sub.materials.end());
    for (graph::PolygonMesh& m : sub.meshes) d.meshes.push_back(std::move(m));
    for (csg::Polygon2& p : sub.polygons) d.polygons.push_back(std::move(p));
    for (std::uint32_t& c : sub.child_refs) c += nodes;
    g.add_child_refs(sub.child_refs.data(), sub.child_refs.size());
    for (graph::Node n : sub.nodes) {
        n.first_child += refs;
        if (n.kind == NK::Transform) n.index += matrices;
        else if (n.kind == NK::Appearance) n.index += materials;
        else if (n.kind == NK::Primitive && n.prim == P::Mesh) n.index += meshes;
        else if (n.kind == NK::Primitive && (n.prim == P::Prism || n.prim == P::Lathe)) n.index += polygons;
        g.add(std::move(n));
    }
    return sub.root + nodes;
}

}  // namespace kerf::eval
