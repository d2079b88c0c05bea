// Test helper: builds csg::Scene values directly (no interpreter), from a
// small tree, with conservative leaf bounds (the transformed corners of the
// primitive's object-space box) and node bounds clipped as lowering does.
#pragma once
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "csg/scene.hpp"

namespace kerf::test {

struct Tree {
    csg::Op op = csg::Op::Leaf;
    csg::Leaf leaf;  // Leaf only
    std::vector<Tree> kids;
};

inline csg::Aabb object_box(const csg::Leaf& l) {
    using csg::PrimKind;
    const double* p = l.p;
    switch (l.kind) {
        case PrimKind::Sphere: return {glm::dvec3(-p[0]), glm::dvec3(p[0])};
        case PrimKind::Box: return {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}};
        case PrimKind::Cylinder: {
            const double r = std::max(p[2], p[3]);
            return {{-r, -r, p[0]}, {r, r, p[1]}};
        }
        case PrimKind::Torus: return {{-(p[0] + p[1]), -(p[0] + p[1]), -p[1]}, {p[0] + p[1], p[0] + p[1], p[1]}};
        case PrimKind::Paraboloid: return {{-p[1], -p[1], 0}, {p[1], p[1], p[0]}};
        case PrimKind::Hyperboloid: {
            const double r = std::max(p[1], p[2]);
            return {{-r, -r, -p[0] / 2}, {r, r, p[0] / 2}};
        }
        default: return csg::Aabb::everything();
    }
}

// world_from_object: an affine 4×4 (last row 0 0 0 1).
inline csg::Leaf make_leaf(csg::PrimKind kind, std::vector<double> params, const glm::dmat4& world_from_object = glm::dmat4(1.0),
                           std::uint32_t material = 0) {
    csg::Leaf l;
    l.kind = kind;
    l.material = material;
    for (std::size_t i = 0; i < params.size() && i < 6; ++i) l.p[i] = params[i];
    l.world_from_object.linear = glm::dmat3(world_from_object);
    l.world_from_object.offset = glm::dvec3(world_from_object[3]);
    const glm::dmat4 inv = glm::inverse(world_from_object);
    l.object_from_world.linear = glm::dmat3(inv);
    l.object_from_world.offset = glm::dvec3(inv[3]);
    const csg::Aabb ob = object_box(l);
    if (kind == csg::PrimKind::Plane) {
        l.bounds = csg::Aabb::everything();
    } else {
        for (int c = 0; c < 8; ++c)
            l.bounds.extend(l.world_from_object.point(
                {(c & 1) ? ob.hi.x : ob.lo.x, (c & 2) ? ob.hi.y : ob.lo.y, (c & 4) ? ob.hi.z : ob.lo.z}));
    }
    return l;
}

inline Tree leaf(csg::Leaf l) { return Tree{csg::Op::Leaf, std::move(l), {}}; }
inline Tree op(csg::Op o, std::vector<Tree> kids) { return Tree{o, {}, std::move(kids)}; }

namespace detail {
inline std::uint32_t flatten(const Tree& t, std::uint32_t parent, csg::Scene& s) {
    const std::uint32_t id = std::uint32_t(s.nodes.size());
    s.nodes.push_back({});
    s.nodes[id].op = t.op;
    s.nodes[id].parent = parent;
    if (t.op == csg::Op::Leaf) {
        s.nodes[id].first = std::uint32_t(s.leaves.size());
        s.nodes[id].count = 0;
        s.nodes[id].bounds = t.leaf.bounds;
        s.leaves.push_back(t.leaf);
        return id;
    }
    const std::uint32_t first = std::uint32_t(s.children.size());
    s.nodes[id].first = first;
    s.nodes[id].count = std::uint32_t(t.kids.size());
    s.children.resize(first + t.kids.size());
    csg::Aabb b;
    for (std::size_t k = 0; k < t.kids.size(); ++k) {
        const std::uint32_t c = flatten(t.kids[k], id, s);
        s.children[first + k] = c;
        const csg::Aabb& cb = s.nodes[c].bounds;
        if (t.op == csg::Op::Union) b.extend(cb);
        else if (k == 0) b = cb;
        else if (t.op == csg::Op::Intersection) b = csg::Aabb::overlap(b, cb);
    }
    s.nodes[id].bounds = b;
    return id;
}
}  // namespace detail

// A scene around `root` with one default material (plus `materials`), a
// camera and one light.
inline csg::Scene make_scene(const Tree& root, std::vector<csg::Material> materials = {csg::Material{}}) {
    csg::Scene s;
    s.root = detail::flatten(root, csg::kNone, s);
    s.materials = std::move(materials);
    s.camera.position = {0, -6, 2};
    s.camera.look_at = {0, 0, 0};
    s.lights.push_back(csg::Light{false, {-5, -8, 10}, {0, 0, -1}, {1, 1, 1}, 1});
    return s;
}

// An orthographic camera straight down -z onto `at` from `above`, +y up,
// `height` units of the scene across the image.
inline void look_down(csg::Scene& s, glm::dvec3 at, double above, double height) {
    s.camera.orthographic = true;
    s.camera.position = at + glm::dvec3(0, 0, above);
    s.camera.look_at = at;
    s.camera.up = {0, 1, 0};
    s.camera.height = height;
}

inline glm::dmat4 translate(double x, double y, double z) { return glm::translate(glm::dmat4(1.0), {x, y, z}); }
inline glm::dmat4 scale(double x, double y, double z) { return glm::scale(glm::dmat4(1.0), {x, y, z}); }
inline glm::dmat4 rotate_deg(double deg, glm::dvec3 axis) { return glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis); }

inline csg::Leaf sphere(double r, const glm::dmat4& m = glm::dmat4(1.0), std::uint32_t mat = 0) {
    return make_leaf(csg::PrimKind::Sphere, {r}, m, mat);
}
inline csg::Leaf box(glm::dvec3 lo, glm::dvec3 hi, const glm::dmat4& m = glm::dmat4(1.0), std::uint32_t mat = 0) {
    return make_leaf(csg::PrimKind::Box, {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}, m, mat);
}

}  // namespace kerf::test
