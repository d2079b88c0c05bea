// lower_to_csg: flatten and prune (flat_tree.cpp), lay out (flat_tree_emit.cpp),
// then the scene statements or their docs/spec.md §6 defaults (defaults.cpp).
#include "lower/lower.hpp"

#include "lower/flat_tree.hpp"
#include "lower/defaults.hpp"
#include "lower/geometry_ops.hpp"

namespace kerf {

namespace {

void apply_scene_statements(const graph::SceneGraph& g, csg::Scene& s) {
    if (g.camera) {
        s.camera = *g.camera;
    } else {
        // Located at the top of the main file: the default camera belongs
        // to no statement of its own.
        const SourceLoc& where = g.nodes.empty() ? SourceLoc{} : g.nodes[g.root].loc;
        s.camera = default_camera(framing_box(s), where);
    }
    s.lights = g.lights.empty() ? default_lights(s.camera) : g.lights;
    s.background = g.background.value_or(glm::dvec3(0.2, 0.2, 0.2));
    s.ambient_occlusion = g.ambient_occlusion.value_or(csg::AmbientOcclusion{});
    s.fog = g.fog.value_or(csg::Fog{});
}

}  // namespace

csg::Scene lower_to_csg(const graph::SceneGraph& input) {
    graph::SceneGraph resolved;  // hull(), minkowski(), resize() replaced, when there are any
    const graph::SceneGraph& graph = resolve_geometry_ops(input, resolved) ? resolved : input;
    csg::Scene scene;
    const lowering::FlatTree tree = lowering::build_flat_tree(graph, scene.leaves);
    lowering::emit_flat_tree(graph, tree, scene);
    apply_scene_statements(graph, scene);
    return scene;
}

}  // namespace kerf
