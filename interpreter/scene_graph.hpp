// What evaluating a script produces (the interpreter's output, lowering's
// input): solids, booleans, transforms and appearance scopes as one arena,
// children stored before parents, plus the scene statements of docs/spec.md §6.
// Primitive parameters are already validated and canonical (a cube is its
// two corners, a cylinder its z-range and two radii) so later stages never
// re-interpret OpenSCAD's argument conventions. Primitive kinds, materials,
// the camera and lights are the contract's own types (csg/scene.hpp): one
// vocabulary from the evaluator to the renderer.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "grammar/source.hpp"

namespace kerf::graph {

enum class NodeKind : std::uint8_t {
    Primitive,     // leaf
    Union,         // children: any number (0 = empty solid)
    Intersection,  // children: any number (0 = empty solid)
    Difference,    // children[0] minus the rest (0 children = empty solid)
    Transform,     // one child (a union of the block); matrix index
    Appearance,    // one child; material index applies to leaves without an inner one
    // The 3D operations lowering resolves into ordinary nodes before it
    // flattens (lower/geometry_ops.hpp, docs/lowering.md "Hull, Minkowski,
    // resize"): they need the children's exact boxes or points.
    Hull,          // any number of children; p[0] = tessellation tolerance of curved children
    Minkowski,     // any number of children; p[0] = tessellation tolerance of curved children
    Resize,        // one child; p[0..2] = newsize, p[3..5] = auto (1 or 0), OpenSCAD's rule
};

struct Node {
    NodeKind kind = NodeKind::Union;
    csg::PrimKind prim = csg::PrimKind::Sphere;  // Primitive only
    std::uint32_t first_child = 0;     // into SceneGraph::child_refs
    std::uint32_t child_count = 0;
    std::uint32_t index = 0;           // Primitive: mesh index (Mesh only);
                                       // Transform: into matrices; Appearance: into materials
    double p[6] = {0, 0, 0, 0, 0, 0};  // Primitive parameters (csg::PrimKind says which)
    SourceLoc loc;                     // the statement that produced the node
    // A 2D shape (docs/spec.md §10), carried as its extrusion over the unit
    // slab 0 < z < 1: square a Box, circle a Cylinder, polygon a Prism; 2D
    // transforms keep z, so every extrusion without twist or scale is a z
    // map of it (docs/lowering.md, "2D shapes").
    bool flat = false;
};

struct PolygonMesh {  // as written: polygon faces; lowering triangulates into csg::Mesh
    std::vector<glm::dvec3> points;
    std::vector<std::vector<std::uint32_t>> faces;  // OpenSCAD order (clockwise seen from outside)
    bool solid = true;
};

struct SceneGraph {
    std::vector<Node> nodes;                 // children always before parents
    std::vector<std::uint32_t> child_refs;   // node indices, per node a contiguous run
    std::vector<glm::dmat4> matrices;        // Transform: world_from_child (affine)
    std::vector<csg::Material> materials;
    std::vector<PolygonMesh> meshes;
    std::vector<csg::Polygon2> polygons;     // Prism: polygon sections
    std::uint32_t root = 0;                  // a Union node (implicit top-level union)
    // The roots of the `%` and `#` ghosts (csg/ghosts.hpp), indexed by
    // csg::GhostKind: Unions over the ghost subtrees, each under its
    // statement's world transform and colour, in the same arena (a `#`
    // subtree is shared with the solid); csg::kNone: no such ghost.
    std::uint32_t ghost_roots[2] = {csg::kNone, csg::kNone};

    std::optional<csg::Camera> camera;            // none: lowering applies docs/spec.md §6 defaults
    std::vector<csg::Light> lights;              // empty: default lights
    std::optional<glm::dvec3> background;    // none: default dark grey
    std::optional<csg::AmbientOcclusion> ambient_occlusion;  // none: off
    std::optional<csg::Fog> fog;                             // none: clear air
};

}  // namespace kerf::graph
