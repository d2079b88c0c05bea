// lower_to_csg: flatten and prune (flat_tree.cpp), lay out (flat_tree_emit.cpp),
// then the scene statements or their docs/spec.md §6 defaults (defaults.cpp).
#include "lower/lower.hpp"

#include <algorithm>

#include "csg/ghosts.hpp"

#include "lower/flat_tree.hpp"
#include "lower/defaults.hpp"
#include "lower/geometry_ops.hpp"
#include "lower/studio.hpp"

namespace kerf {

namespace {

// Each part a script leaves unset gets the look's: the camera, the lights
// (with the studio look, the ground that catches their shadows and the
// light background come with them), the background (docs/language.md,
// "The default look").
// `top`: where the default camera is said to come from.
void apply_scene_statements(const graph::SceneGraph& g, const SourceLoc& top, const LowerOptions& o, csg::Scene& s) {
    const bool studio = o.look == Look::Studio;
    // The default camera frames the ghosts too, as OpenSCAD's preview does.
    csg::Aabb frame = framing_box(s);
    if (!s.ghosts.empty()) {
        frame = s.root == csg::kNone ? csg::Aabb{} : frame;
        for (const csg::Scene& ghost : s.ghosts) frame.extend(framing_box(ghost));
    }
    if (g.camera) {
        s.camera = *g.camera;
    } else {
        s.camera = studio ? studio_camera(frame, o.aspect, top) : default_camera(frame, top);
    }
    if (!g.lights.empty()) s.lights = g.lights;
    else if (!studio) s.lights = default_lights(s.camera);
    else {
        s.lights = studio_lights(s.camera, frame);
        // Under the lowest point of a bounded solid (an unbounded one, a
        // half-space, is its own floor; an empty scene has nothing to ground).
        s.ground.on = s.root != csg::kNone && finite_box(s.bounds());
        s.ground.z = s.ground.on ? s.bounds().lo.z : 0;
        // A ghost below the solid (a `%` build plate) stands on the ground too.
        for (const csg::Scene& ghost : s.ghosts)
            if (s.ground.on && finite_box(ghost.bounds())) s.ground.z = std::min(s.ground.z, ghost.bounds().lo.z);
    }
    // The light background comes with the studio lights: a script that
    // lights itself keeps the dark one its lights were chosen against.
    const bool studio_lit = studio && g.lights.empty();
    s.background = g.background.value_or(studio_lit ? glm::dvec3(kStudioBackground) : glm::dvec3(0.2, 0.2, 0.2));
    s.ambient_occlusion = g.ambient_occlusion.value_or(csg::AmbientOcclusion{});
    s.fog = g.fog.value_or(csg::Fog{});
}

// The node arrays: what only build_flat_tree reads.
void release_nodes(graph::SceneGraph& g) {
    std::vector<graph::Node>().swap(g.nodes);
    std::vector<std::uint32_t>().swap(g.child_refs);
    g.matrices = graph::Transforms{};
}

// `owned`: the input when the caller gave it up; its nodes are freed as
// soon as the flat tree holds what they said, so the graph and the scene's
// nodes never coexist (docs/performance.md, "Memory").
csg::Scene lower(const graph::SceneGraph& input, graph::SceneGraph* owned, const LowerOptions& options) {
    // Located at the top of the main file: the default camera belongs to
    // no statement of its own.
    const SourceLoc top = input.nodes.empty() ? SourceLoc{} : input.nodes[input.root].loc;
    graph::SceneGraph resolved;  // hull(), minkowski(), resize() replaced, when there are any
    const bool ops = resolve_geometry_ops(input, resolved);
    if (ops && owned) release_nodes(*owned);
    const graph::SceneGraph& graph = ops ? resolved : input;
    csg::Scene scene;
    const lowering::FlatTree tree = lowering::build_flat_tree(graph, scene.leaves, csg::kNone, options.threads);
    // The ghosts' trees are flattened too before the nodes go.
    struct Ghost {
        csg::GhostKind kind;
        csg::Scene scene;
        lowering::FlatTree tree;
    };
    std::vector<Ghost> ghosts;
    if (options.ghosts)
        for (csg::GhostKind kind : {csg::GhostKind::Background, csg::GhostKind::Highlight}) {
            const std::uint32_t root = graph.ghost_roots[std::size_t(kind)];
            if (root == csg::kNone) continue;
            Ghost& g = ghosts.emplace_back(Ghost{kind, csg::Scene{}, {}});
            g.tree = lowering::build_flat_tree(graph, g.scene.leaves, root, options.threads);
        }
    if (ops) release_nodes(resolved);
    else if (owned) release_nodes(*owned);
    lowering::emit_flat_tree(graph, tree, scene, options.threads);
    for (auto& [kind, ghost, ghost_tree] : ghosts) {
        lowering::emit_flat_tree(graph, ghost_tree, ghost, options.threads);
        if (ghost.root == csg::kNone) continue;
        ghost.ghost_kind = kind;
        // A `#` part is the highlight colour whatever colours it has inside.
        if (kind == csg::GhostKind::Highlight)
            for (csg::Material& m : ghost.materials) m = csg::ghost_material(kind);
        scene.ghosts.push_back(std::move(ghost));
    }
    apply_scene_statements(graph, top, options, scene);
    return scene;
}

}  // namespace

csg::Scene lower_to_csg(const graph::SceneGraph& graph, const LowerOptions& options) {
    return lower(graph, nullptr, options);
}

csg::Scene lower_to_csg(graph::SceneGraph&& graph, const LowerOptions& options) {
    return lower(graph, &graph, options);
}

}  // namespace kerf
