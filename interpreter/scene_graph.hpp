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
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "csg/huge_pages.hpp"
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
    // A 2D shape (docs/spec.md §10), carried as its extrusion over the unit
    // slab 0 < z < 1: square a Box, circle a Cylinder, polygon a Prism; 2D
    // transforms keep z, so every extrusion without twist or scale is a z
    // map of it (docs/lowering.md, "2D shapes"). Beside the kinds, not at
    // the end: 88 bytes a node instead of 96 (docs/performance.md, "Memory").
    bool flat = false;
    std::uint32_t first_child = 0;     // into SceneGraph::child_refs
    std::uint32_t child_count = 0;
    std::uint32_t index = 0;           // Primitive: mesh index (Mesh only);
                                       // Transform: into matrices; Appearance: into materials
    double p[6] = {0, 0, 0, 0, 0, 0};  // Primitive parameters (csg::PrimKind says which)
    SourceLoc loc;                     // the statement that produced the node
};

struct PolygonMesh {  // as written: polygon faces; lowering triangulates into csg::Mesh
    std::vector<glm::dvec3> points;
    std::vector<std::vector<std::uint32_t>> faces;  // OpenSCAD order (clockwise seen from outside)
    bool solid = true;
};

// The Transform nodes' matrices (world_from_child). Most are translations
// (a loop's translate() per leaf): those keep only their offset, 24 bytes
// instead of a 128-byte matrix, so a million translated spheres hold 28 MB
// here instead of 128 MB (docs/performance.md, "Memory"). A read returns
// the matrix that was stored, bit for bit.
class Transforms {
public:
    std::size_t size() const { return slots_.size(); }
    bool empty() const { return slots_.empty(); }
    std::size_t capacity() const { return slots_.capacity(); }
    // Address space only: pages are touched as transforms arrive.
    void reserve(std::size_t n) {
        slots_.reserve(n);
        offsets_.reserve(n);
        general_.reserve(n);
    }
    // The same on huge pages (csg/huge_pages.hpp: a hint).
    void reserve_huge(std::size_t n) {
        csg::reserve_huge(slots_, n);
        csg::reserve_huge(offsets_, n);
        csg::reserve_huge(general_, n);
    }
    // The arrays a translation's push_back grows: the interpreter has their
    // pages faulted in ahead (interpreter/graph_builder.hpp).
    const std::vector<std::uint32_t>& slot_array() const { return slots_; }
    const std::vector<glm::dvec3>& offset_array() const { return offsets_; }
    glm::dmat4 operator[](std::size_t i) const {
        const std::uint32_t s = slots_[i];
        if (s & kGeneral) return general_[s & ~kGeneral];
        glm::dmat4 m(1.0);
        m[3] = glm::dvec4(offsets_[s], 1.0);
        return m;
    }
    // Transform i's offset when it is a translation (its matrix the
    // identity's but for the offset), else null: lowering composes those
    // without the matrix product.
    const glm::dvec3* translation_offset(std::size_t i) const {
        const std::uint32_t s = slots_[i];
        return (s & kGeneral) ? nullptr : &offsets_[s];
    }
    glm::dmat4 at(std::size_t i) const {
        if (i >= size()) throw std::out_of_range("Transforms::at");
        return (*this)[i];
    }
    void push_back(const glm::dmat4& m) { slots_.push_back(append(m)); }
    // Replaces transform i (a translation may become a general matrix).
    void set(std::size_t i, const glm::dmat4& m) {
        const std::uint32_t s = slots_[i];
        if (translation(m) != !(s & kGeneral)) slots_[i] = append(m);  // the old entry is left unused
        else if (s & kGeneral) general_[s & ~kGeneral] = m;
        else offsets_[s] = glm::dvec3(m[3]);
    }
    // Drops the transforms from n on (rolling back a trial build).
    void resize(std::size_t n) {
        while (slots_.size() > n) {
            const std::uint32_t s = slots_.back();
            slots_.pop_back();
            if (s & kGeneral) {
                if ((s & ~kGeneral) + 1 == general_.size()) general_.pop_back();
            } else if (s + 1 == offsets_.size()) {
                offsets_.pop_back();
            }
        }
    }

private:
    static constexpr std::uint32_t kGeneral = 0x80000000u;
    // A translation: the linear part and the last row exactly those of the
    // identity, bit for bit (so -0.0 is kept as a general matrix).
    static bool translation(const glm::dmat4& m) {
        static const glm::dmat4 id(1.0);
        return std::memcmp(&m[0], &id[0], sizeof(glm::dvec4) * 3) == 0 && std::memcmp(&m[3][3], &id[3][3], sizeof(double)) == 0;
    }
    std::uint32_t append(const glm::dmat4& m) {
        if (offsets_.size() + general_.size() >= kGeneral) throw std::length_error("too many transforms");
        if (translation(m)) {
            offsets_.emplace_back(m[3]);
            return static_cast<std::uint32_t>(offsets_.size() - 1);
        }
        general_.push_back(m);
        return static_cast<std::uint32_t>(general_.size() - 1) | kGeneral;
    }

    std::vector<std::uint32_t> slots_;  // offsets_ index, or general_ index | kGeneral
    std::vector<glm::dvec3> offsets_;
    std::vector<glm::dmat4> general_;
};

struct SceneGraph {
    std::vector<Node> nodes;                 // children always before parents
    std::vector<std::uint32_t> child_refs;   // node indices, per node a contiguous run
    Transforms matrices;                     // Transform: world_from_child (affine)
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
