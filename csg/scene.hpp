// The contract between the interpreter and the renderer (architecture.md):
// plain contiguous arrays, no transform nodes, no virtual calls, no pointers
// into the AST. Lowering writes it; the renderer only reads it.
#pragma once
#include <cstdint>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "csg/texture.hpp"

namespace kerf::csg {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// The scale range the renderer promises a correct picture in: solids,
// cameras and lights within ±1e30 of the origin, and a view at least 1e-30
// across (a camera that far from what it looks at, or a default camera
// framing a solid that large) (docs/accuracy.md, "Range"). Beyond it the
// tracer's float BVH boxes or its squared terms would overflow or
// underflow; lowering and the scene statements refuse it.
constexpr double kRenderableRange = 1e30;

// The deepest operation tree the renderer evaluates: nodes on the path from
// the root to a leaf, both counted, after lowering has merged nested unions
// and intersections. The tracer recurses once per level; its threads' stacks
// are sized for this depth (docs/lowering.md, "Depth"). Lowering refuses a
// deeper tree at the node that exceeds it; render() refuses one too.
constexpr std::uint32_t kMaxDepth = 4000;

struct Aabb {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const glm::dvec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void extend(const Aabb& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    static Aabb overlap(const Aabb& a, const Aabb& b) { return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)}; }
    static Aabb everything() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {glm::dvec3(-inf), glm::dvec3(inf)};
    }
};

// p' = linear * p + offset
struct Affine {
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};
    glm::dvec3 point(const glm::dvec3& p) const { return linear * p + offset; }
    glm::dvec3 vector(const glm::dvec3& v) const { return linear * v; }
};

// A primitive's kind and the meaning of its canonical parameters p[], the
// same in the interpreter's scene graph and in Leaf (object space).
enum class PrimKind : std::uint8_t {
    Sphere,       // p[0] = radius; centred at the origin
    Box,          // p[0..2] = min corner, p[3..5] = max corner
    Cylinder,     // p[0] = z0, p[1] = z1 (> z0), p[2] = radius at z0, p[3] = radius at z1
                  //   (frusta and cones too; at most one radius is 0)
    Torus,        // p[0] = major R, p[1] = minor r (0 < r < R); XY plane, origin
    Plane,        // p[0..2] = unit normal, p[3] = offset: {x : dot(n,x) <= offset}
    Paraboloid,   // p[0] = h, p[1] = r: z >= h(x²+y²)/r², z <= h
    Hyperboloid,  // p[0] = h, p[1] = r (radius at z = ±h/2), p[2] = waist (radius at z = 0)
    Mesh,         // graph: index into SceneGraph::meshes; Leaf: Leaf::mesh
    Prism,        // p[0] = z0, p[1] = z1 (> z0): a polygon set (even-odd) times the slab z0 < z < z1,
                  //   the section at τ = (z − z0)/(z1 − z0) is scale(1 + p[2]·τ, 1 + (p[2] + p[3])·τ) ·
                  //   rotate(−p[4]·τ radians) · polygon (p[2], p[2] + p[3] >= −1; all 0: straight);
                  //   graph: index into SceneGraph::polygons; Leaf: Leaf::polygon
    Lathe,        // a polygon set (even-odd) in the half-plane x >= 0 (x = radius, y = height) revolved
                  //   about Z; no parameters; graph: SceneGraph::polygons; Leaf: Leaf::polygon
};

// A 2D polygon set filled by the even-odd rule (docs/spec.md §10: OpenSCAD's
// rule for paths, holes, self-intersecting and overlapping paths): a point
// is inside when a ray from it crosses the closed paths an odd number of
// times. Stored as its edges; a path's closing edge is one of them.
struct Polygon2 {
    std::vector<glm::dvec4> edges;  // (x0, y0, x1, y1), one per path edge
    glm::dvec2 lo{0}, hi{0};        // the box of the vertices
};

struct Leaf {
    PrimKind kind = PrimKind::Sphere;
    std::uint32_t material = 0;
    std::uint32_t mesh = kNone;        // Mesh only
    std::uint32_t polygon = kNone;     // Prism and Lathe only: into Scene::polygons
    std::uint32_t source = kNone;      // into Scene::sources
    // Into Scene::material_frames: world point -> the coordinates its
    // material() call was written in (the transforms outside that call
    // undone), so a pattern moves with the solid it is applied to. A table,
    // not a field: most leaves share one frame (0, the identity, for every
    // unpatterned leaf), and 96 bytes a leaf was a tenth of a 10^6-sphere
    // render's memory (docs/performance.md, "Memory").
    std::uint32_t material_frame = 0;
    double p[6] = {0, 0, 0, 0, 0, 0};  // shape parameters, object space
    Affine object_from_world;          // world point -> object point
    Affine world_from_object;          // its inverse
    // Object-space normal -> world-space normal: the transpose of
    // object_from_world.linear, which keeps normals outward under mirrors
    // too. Applied, not stored: a row-vector product costs what the matrix
    // product did, and the stored matrix was 72 bytes a leaf.
    glm::dvec3 normal_to_world(const glm::dvec3& n_obj) const { return n_obj * object_from_world.linear; }
    Aabb bounds;                       // tight world box of the transformed primitive
};

enum class Op : std::uint8_t { Leaf, Union, Intersection, Difference };

struct Node {
    Op op = Op::Union;
    std::uint32_t first = 0;   // Leaf: leaf index; others: start in Scene::children
    std::uint32_t count = 0;   // number of children (Difference: children[first] is the minuend)
    std::uint32_t parent = kNone;
    Aabb bounds;               // clipped by the operation (intersection: overlap; difference: minuend)
};

// A procedural pattern blends Material::color (value 0) and color2
// (value 1) by a value in [0, 1] that depends only on the shading point in
// the material's pattern space (docs/language.md, "Patterns").
// Image: the colour is looked up in Material::texture instead (csg/texture.hpp).
enum class Pattern : std::uint8_t { None, Checker, Stripes, Gradient, Noise, Marble, Wood, Image };

struct Material {
    glm::dvec3 color{0.8, 0.8, 0.8};     // linear RGB
    glm::dvec3 interior{0.8, 0.8, 0.8};  // shown on cut faces that expose this solid's inside
    double diffuse = 0.8;
    double specular = 0.2;
    double shininess = 32;
    double reflect = 0;
    // A dielectric (docs/language.md, "Glass"): the share of light that
    // crosses the surface, split there by Fresnel's equations between a
    // reflected and a refracted ray (Snell, index `ior` inside the solid,
    // 1 outside); `color(c, alpha)` sets transparency = 1 − alpha. Light
    // travelling a distance d inside is scaled by exp(−absorption·d) per
    // channel (Beer–Lambert; absorption per unit length, linear RGB).
    double transparency = 0;
    double ior = 1;
    glm::dvec3 absorption{0.0};
    // Glossy reflection: the mirror ray of `reflect` spread over a cone
    // whose half-angle grows with roughness (0: a perfect mirror).
    double roughness = 0;
    glm::dvec3 emission{0.0};            // linear RGB radiance the surface gives off by itself
    Pattern pattern = Pattern::None;
    glm::dvec3 color2{0.0};              // linear RGB where the pattern's value is 1
    // Pattern coordinates from the coordinates of the material() call:
    // the inverse of pattern_transform, then divided by pattern_scale.
    Affine pattern_from_material;
    // pattern == Image: the decoded image (shared by every material naming
    // the file), how pattern space maps onto it, and whether it is read
    // bilinearly between pixel centres or by the nearest pixel.
    std::shared_ptr<const Texture> texture;
    TextureMapping mapping = TextureMapping::Planar;
    bool bilinear = true;
};

struct Mesh {
    std::vector<glm::dvec3> points;             // object space
    std::vector<std::uint32_t> triangles;        // 3 indices per triangle, outward winding (CCW seen from outside)
    bool solid = true;
};

struct AmbientOcclusion {
    int samples = 0;
    double distance = std::numeric_limits<double>::infinity();
};

// How pixels map to directions (docs/spec.md §12). Planar: the pinhole or,
// with Camera::orthographic, the parallel projection of §6. Fisheye:
// equidistant, the image circle inscribed in the shorter side spanning
// `fov` degrees across. Panoramic: equirectangular, `fov` degrees of
// longitude across the width and fov / 2 of latitude down the height.
enum class Projection : std::uint8_t { Planar, Fisheye, Panoramic };

struct Camera {
    glm::dvec3 position{0, -10, 5};
    glm::dvec3 look_at{0, 0, 0};
    glm::dvec3 up{0, 0, 1};
    double fov = 40;           // vertical, degrees (fisheye, panoramic: see Projection)
    bool orthographic = false;
    double height = 1;         // orthographic view height
    Projection projection = Projection::Planar;
    // Depth of field (perspective only): a thin lens `aperture` across,
    // sharp at `focal_distance` along the view direction, each pixel the
    // mean of `blur_samples` rays over lens and pixel; aperture 0: a pinhole.
    double aperture = 0;
    double focal_distance = 1;
    std::uint32_t blur_samples = 16;
};

// fog(distance, color): POV-Ray's constant fog. A ray that travels s keeps
// exp(−s / distance) of what it sees, the rest is `color`; a ray that
// escapes sees `color` alone. An infinite distance: no fog.
struct Fog {
    double distance = std::numeric_limits<double>::infinity();
    glm::dvec3 color{0, 0, 0};
    bool on() const { return distance < std::numeric_limits<double>::infinity(); }
};

// The studio look's ground (docs/spec.md §12 "Default look"): a rendering
// element, not a solid — no leaf, no node, unseen by the membership oracle,
// `kerf measure` and the AOVs. A shadow catcher: the horizontal plane
// z = `z`, seen only from above, shows what a miss shows (the background, or
// the fog's colour) darkened by `shadow` times the share of the
// shadow-casting lights' light that the solid blocks there (render/ground.*).
struct Ground {
    bool on = false;
    double z = 0;
    double shadow = 0.6;  // 0..1: how dark a full shadow is
};

struct Light {
    bool directional = false;
    glm::dvec3 position{0, 0, 0};
    glm::dvec3 direction{0, 0, -1};  // direction the light travels (distant light; a spot's axis)
    glm::dvec3 color{1, 1, 1};
    double intensity = 1;
    // A spherical light (point lights and spots): radius > 0 casts soft
    // shadows, estimated with `samples` shadow rays per shading point.
    double radius = 0;
    std::uint32_t samples = 16;
    // Probe first (the studio key light): 5 shadow rays to the sphere's rim
    // and centre; only where they disagree the `samples` rays (docs/language.md, "The
    // default look"; the bias in docs/quality.md).
    bool probe = false;
    bool shadows = true;         // false: the light reaches every point facing it
    bool inverse_square = false; // intensity is at distance 1, falling as 1/d²
    // A spot: full intensity within `spot_angle` (degrees, from the axis
    // `direction`), fading smoothly to none at spot_angle + spot_falloff.
    bool spot = false;
    double spot_angle = 30, spot_falloff = 5;
};

struct SourceRef {
    std::uint32_t file = 0;  // into Scene::files
    std::uint32_t line = 0;
    std::uint32_t col = 0;
};

// Of a ghost scene (Scene::ghosts, csg/ghosts.hpp): a `%` part or a `#` one.
enum class GhostKind : std::uint8_t { Background, Highlight };

struct Scene {
    std::vector<Leaf> leaves;
    std::vector<Node> nodes;              // pre-order: parents before children; root = nodes[0]
    std::vector<std::uint32_t> children;  // node indices, a contiguous run per operation node
    std::uint32_t root = kNone;           // kNone: the scene has no solid at all

    std::vector<Material> materials;      // at least one (the default light grey)
    std::vector<Affine> material_frames{Affine{}};  // Leaf::material_frame; 0 = the identity, each frame once
    std::vector<Mesh> meshes;
    std::vector<Polygon2> polygons;       // Prism and Lathe leaves' sections, each stored once
    Camera camera;                        // always resolved (docs/spec.md §6 defaults applied)
    std::vector<Light> lights;            // always resolved (defaults applied)
    glm::dvec3 background{0.2, 0.2, 0.2};
    // ambient_occlusion(samples, distance) (render/ao.hpp): the ambient term
    // scaled by the share of the hemisphere open within `distance`; 0 samples: off.
    AmbientOcclusion ambient_occlusion;
    Fog fog;
    Ground ground;                        // off unless the studio look set it (lower/studio.*)

    std::vector<SourceRef> sources;
    std::vector<std::string> files;

    // The translucent layers OpenSCAD's preview draws over the solid
    // (csg/ghosts.hpp): the `%` parts, then the `#` parts, each a scene of
    // its own (leaves, nodes, materials; no camera or lights) whose
    // materials give each surface's colour and, as 1 − transparency, its
    // opacity. Empty: none, or `--no-ghosts`.
    std::vector<Scene> ghosts;
    GhostKind ghost_kind = GhostKind::Background;  // a ghost scene's kind (`kerf dump` names it)

    Aabb bounds() const { return root == kNone ? Aabb{} : nodes[root].bounds; }
};

}  // namespace kerf::csg
