// Builds scene graphs by hand for the lowering tests, so they do not depend
// on the parser or the evaluator. Children are created before their parents,
// as in the interpreter's arena.
#pragma once
#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "interpreter/scene_graph.hpp"

namespace kerf::test {

using graph::NodeKind;
using csg::PrimKind;

struct GraphBuilder {
    graph::SceneGraph g;
    std::shared_ptr<const SourceFile> file = std::make_shared<SourceFile>(SourceFile{"test.sdl", ""});
    std::uint32_t next_line = 1;

    std::uint32_t add(graph::Node n, std::vector<std::uint32_t> kids = {}) {
        n.first_child = static_cast<std::uint32_t>(g.child_refs.size());
        n.child_count = static_cast<std::uint32_t>(kids.size());
        for (auto k : kids) g.child_refs.push_back(k);
        if (!n.loc.file) n.loc = {file, next_line++, 1};
        g.nodes.push_back(n);
        return static_cast<std::uint32_t>(g.nodes.size() - 1);
    }

    std::uint32_t prim(PrimKind k, std::initializer_list<double> p) {
        graph::Node n;
        n.kind = NodeKind::Primitive;
        n.prim = k;
        int i = 0;
        for (double v : p) n.p[i++] = v;
        return add(n);
    }
    std::uint32_t sphere(double r = 1) { return prim(PrimKind::Sphere, {r}); }
    std::uint32_t box(glm::dvec3 lo, glm::dvec3 hi) { return prim(PrimKind::Box, {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}); }
    std::uint32_t cube(double s = 1) { return box(glm::dvec3(0), glm::dvec3(s)); }
    std::uint32_t cylinder(double z0, double z1, double r0, double r1) { return prim(PrimKind::Cylinder, {z0, z1, r0, r1}); }
    std::uint32_t torus(double R, double r) { return prim(PrimKind::Torus, {R, r}); }
    std::uint32_t plane(glm::dvec3 n, double d) { return prim(PrimKind::Plane, {n.x, n.y, n.z, d}); }
    std::uint32_t paraboloid(double h, double r) { return prim(PrimKind::Paraboloid, {h, r}); }
    std::uint32_t hyperboloid(double h, double r, double w) { return prim(PrimKind::Hyperboloid, {h, r, w}); }
    std::uint32_t mesh(std::uint32_t index) {
        graph::Node n;
        n.kind = NodeKind::Primitive;
        n.prim = PrimKind::Mesh;
        n.index = index;
        return add(n);
    }

    std::uint32_t op(NodeKind k, std::vector<std::uint32_t> kids) {
        graph::Node n;
        n.kind = k;
        return add(n, std::move(kids));
    }
    std::uint32_t uni(std::vector<std::uint32_t> kids) { return op(NodeKind::Union, std::move(kids)); }
    std::uint32_t inter(std::vector<std::uint32_t> kids) { return op(NodeKind::Intersection, std::move(kids)); }
    std::uint32_t diff(std::vector<std::uint32_t> kids) { return op(NodeKind::Difference, std::move(kids)); }

    std::uint32_t xform(const glm::dmat4& m, std::uint32_t child) {
        graph::Node n;
        n.kind = NodeKind::Transform;
        n.index = static_cast<std::uint32_t>(g.matrices.size());
        g.matrices.push_back(m);
        return add(n, {child});
    }
    std::uint32_t translate(glm::dvec3 v, std::uint32_t c) { return xform(glm::translate(glm::dmat4(1), v), c); }
    std::uint32_t scale(glm::dvec3 v, std::uint32_t c) { return xform(glm::scale(glm::dmat4(1), v), c); }
    std::uint32_t rotate(double deg, glm::dvec3 axis, std::uint32_t c) {
        return xform(glm::rotate(glm::dmat4(1), glm::radians(deg), axis), c);
    }

    std::uint32_t material(const csg::Material& m) {
        g.materials.push_back(m);
        return static_cast<std::uint32_t>(g.materials.size() - 1);
    }
    std::uint32_t color(glm::dvec3 c, std::uint32_t child) {
        csg::Material m;
        m.color = m.interior = c;
        return appearance(material(m), child);
    }
    std::uint32_t appearance(std::uint32_t material_index, std::uint32_t child) {
        graph::Node n;
        n.kind = NodeKind::Appearance;
        n.index = material_index;
        return add(n, {child});
    }

    // The implicit top-level union.
    graph::SceneGraph& finish(std::vector<std::uint32_t> top) {
        g.root = uni(std::move(top));
        return g;
    }
};

}  // namespace kerf::test
