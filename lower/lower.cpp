// lower_to_csg: flatten and prune (flat_tree.cpp), lay out (flat_tree_emit.cpp),
// then the scene statements or their docs/spec.md §6 defaults (scene_defaults.cpp).
#include "lower/lower.hpp"

#include "lower/flat_tree.hpp"
#include "lower/defaults.hpp"

namespace kerf {

namespace {

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
    const lowering::FlatTree tree = lowering::build_flat_tree(graph, scene.leaves);
    lowering::emit_flat_tree(graph, tree, scene);
    apply_scene_statements(graph, scene);
    return scene;
}

}  // namespace kerf
