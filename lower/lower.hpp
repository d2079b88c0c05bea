// Lowering: the scene graph becomes csg::Scene, the renderer's only
// input — flattened n-ary operations, transforms pushed into the leaves,
// clipped bounds, pruned subtrees, resolved materials and scene defaults.
#pragma once
#include "interpreter/scene_graph.hpp"
#include "csg/scene.hpp"

namespace kerf {

// What a script that sets no camera, light or background gets
// (docs/language.md, "The default look"): the studio set-up (lower/studio.hpp)
// or the plain defaults of docs/spec.md §6 (lower/defaults.hpp).
enum class Look { Studio, Plain };

struct LowerOptions {
    Look look = Look::Studio;
    // The image's width / height: the studio camera fills 80 % of the frame
    // of that shape (the plain camera fits any image at least as wide as tall).
    double aspect = 4.0 / 3.0;
    // The `%` and `#` ghosts (csg/ghosts.hpp) as csg::Scene::ghosts; false
    // (`--no-ghosts`, and `kerf measure`): none, as in OpenSCAD's render.
    bool ghosts = true;
    // Threads that may lower a wide union's leaves (the render's --threads;
    // 0: one per hardware thread). The scene is the same bits whatever the count.
    unsigned threads = 1;
};

// Throws SourceError for scene-level problems it can locate (e.g. a
// singular transform reaching a leaf).
csg::Scene lower_to_csg(const graph::SceneGraph& graph, const LowerOptions& options = {});
// The same for a graph the caller is done with: its nodes, child lists and
// transforms are freed as soon as the flattened tree is built, before the
// scene's nodes are written (the peak of a 10^6-leaf lowering,
// docs/performance.md "Memory"); materials, meshes, polygons and the scene
// statements are left.
csg::Scene lower_to_csg(graph::SceneGraph&& graph, const LowerOptions& options = {});

}  // namespace kerf
