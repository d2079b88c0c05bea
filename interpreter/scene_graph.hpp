// What evaluating a script produces (the interpreter's output, lowering's
// input): solids, booleans, transforms and appearance scopes as one arena,
// children stored before parents, plus the scene statements of docs/spec.md §6.
// Primitive parameters are already validated and canonical (a cube is its
// two corners, a cylinder its z-range and two radii) so later stages never
// re-interpret OpenSCAD's argument conventions.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "grammar/source.hpp"

namespace kerf::scene {

enum class PrimKind : std::uint8_t {
    Sphere,       // p[0] = radius; centred at the origin
    Box,          // p[0..2] = min corner, p[3..5] = max corner
    Cylinder,     // p[0] = z0, p[1] = z1 (> z0), p[2] = radius at z0, p[3] = radius at z1
                  //   (frusta and cones too; at most one radius is 0)
    Torus,        // p[0] = major R, p[1] = minor r (0 < r < R); XY plane, origin
    Plane,        // p[0..2] = unit normal, p[3] = offset: {x : dot(n,x) <= offset}
    Paraboloid,   // p[0] = h, p[1] = r: z >= h(x²+y²)/r², z <= h
    Hyperboloid,  // p[0] = h, p[1] = r (radius at z = ±h/2), p[2] = waist (radius at z = 0)
    Mesh,         // mesh index in SceneGraph::meshes
};

enum class NodeKind : std::uint8_t {
    Primitive,     // leaf
    Union,         // children: any number (0 = empty solid)
    Intersection,  // children: any number (0 = empty solid)
    Difference,    // children[0] minus the rest (0 children = empty solid)
    Transform,     // one child (a union of the block); matrix index
    Appearance,    // one child; material index applies to leaves without an inner one
};

struct Node {
    NodeKind kind = NodeKind::Union;
    PrimKind prim = PrimKind::Sphere;  // Primitive only
    std::uint32_t first_child = 0;     // into SceneGraph::child_refs
    std::uint32_t child_count = 0;
    std::uint32_t index = 0;           // Primitive: mesh index (Mesh only);
                                       // Transform: into matrices; Appearance: into materials
    double p[6] = {0, 0, 0, 0, 0, 0};  // Primitive parameters (see PrimKind)
    SourceLoc loc;                     // the statement that produced the node
};

struct Material {
    glm::dvec3 color{0.8, 0.8, 0.8};   // linear RGB in [0,1]
    double alpha = 1.0;
    glm::dvec3 interior{0.8, 0.8, 0.8};  // colour of cut faces (docs/spec.md §5)
    double diffuse = 0.8;
    double specular = 0.2;
    double shininess = 32;
    double reflect = 0;
};

struct Mesh {
    std::vector<glm::dvec3> points;
    std::vector<std::vector<std::uint32_t>> faces;  // OpenSCAD order (clockwise seen from outside)
    bool solid = true;
};

struct Camera {
    glm::dvec3 position{0, 0, 0};
    glm::dvec3 look_at{0, 0, 0};
    glm::dvec3 up{0, 0, 1};
    double fov = 40;              // vertical, degrees (perspective)
    bool orthographic = false;
    double height = 1;            // orthographic view height
    SourceLoc loc;
};

struct Light {
    bool directional = false;
    glm::dvec3 position{0, 0, 0};   // point light
    glm::dvec3 direction{0, 0, -1}; // distant light: direction the light travels
    glm::dvec3 color{1, 1, 1};
    double intensity = 1;
    SourceLoc loc;
};

struct SceneGraph {
    std::vector<Node> nodes;                 // children always before parents
    std::vector<std::uint32_t> child_refs;   // node indices, per node a contiguous run
    std::vector<glm::dmat4> matrices;        // Transform: world_from_child (affine)
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    std::uint32_t root = 0;                  // a Union node (implicit top-level union)

    std::optional<Camera> camera;            // none: lowering applies docs/spec.md §6 defaults
    std::vector<Light> lights;               // empty: default lights
    std::optional<glm::dvec3> background;    // none: default dark grey
};

}  // namespace kerf::scene
