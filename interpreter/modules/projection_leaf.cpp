#include "interpreter/modules/projection_leaf.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval::projection {

namespace {

using P = csg::PrimKind;

glm::dvec3 at(const glm::dmat4& m, glm::dvec3 p) { return glm::dvec3(m * glm::dvec4(p, 1)); }

// Two rings of n points (radius r0 at z0, r1 at z1) joined, and both caps.
void frustum(std::vector<Tri>& out, const glm::dmat4& m, double z0, double z1, double r0, double r1, int n) {
    auto ring = [&](double r, double z, int i) {
        const double t = 2 * std::numbers::pi * i / n;
        return at(m, {r * std::cos(t), r * std::sin(t), z});
    };
    const glm::dvec3 c0 = at(m, {0, 0, z0}), c1 = at(m, {0, 0, z1});
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 a0 = ring(r0, z0, i), b0 = ring(r0, z0, i + 1), a1 = ring(r1, z1, i), b1 = ring(r1, z1, i + 1);
        out.push_back({c0, b0, a0});
        out.push_back({c1, a1, b1});
        out.push_back({a0, b0, b1});
        out.push_back({a0, b1, a1});
    }
}

}  // namespace

std::vector<Tri> leaf_triangles(const graph::SceneGraph& g, const graph::Node& n, const glm::dmat4& m,
                                double tolerance) {
    std::vector<Tri> out;
    const int segments = circle_segments(tolerance);
    switch (n.prim) {
    case P::Box: {
        const glm::dvec3 lo(n.p[0], n.p[1], n.p[2]), hi(n.p[3], n.p[4], n.p[5]);
        auto corner = [&](int i) { return at(m, {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z}); };
        static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& f : kFaces) {
            out.push_back({corner(f[0]), corner(f[1]), corner(f[2])});
            out.push_back({corner(f[0]), corner(f[2]), corner(f[3])});
        }
        return out;
    }
    case P::Mesh: {
        const graph::PolygonMesh& mesh = g.meshes[n.index];
        for (const auto& face : mesh.faces)
            for (std::size_t k = 2; k < face.size(); ++k)  // fanned, as lowering does
                out.push_back({at(m, mesh.points[face[0]]), at(m, mesh.points[face[k - 1]]), at(m, mesh.points[face[k]])});
        return out;
    }
    case P::Cylinder:
        frustum(out, m, n.p[0], n.p[1], n.p[2], n.p[3], segments);
        return out;
    case P::Sphere: {
        const double r = n.p[0];
        const int rings = std::max(2, segments / 2);
        auto pt = [&](int i, int j) {
            const double th = std::numbers::pi * i / rings, ph = 2 * std::numbers::pi * j / segments;
            return at(m, r * glm::dvec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
        };
        for (int i = 0; i < rings; ++i)
            for (int j = 0; j < segments; ++j) {
                out.push_back({pt(i, j), pt(i + 1, j), pt(i + 1, j + 1)});
                out.push_back({pt(i, j), pt(i + 1, j + 1), pt(i, j + 1)});
            }
        return out;
    }
    case P::Torus: {
        const double R = n.p[0], r = n.p[1];
        const int tube = std::max(8, circle_segments(tolerance * R / r));
        auto pt = [&](int i, int j) {
            const double u = 2 * std::numbers::pi * i / segments, v = 2 * std::numbers::pi * j / tube;
            const double rho = R + r * std::cos(v);
            return at(m, {rho * std::cos(u), rho * std::sin(u), r * std::sin(v)});
        };
        for (int i = 0; i < segments; ++i)
            for (int j = 0; j < tube; ++j) {
                out.push_back({pt(i, j), pt(i + 1, j), pt(i + 1, j + 1)});
                out.push_back({pt(i, j), pt(i + 1, j + 1), pt(i, j + 1)});
            }
        return out;
    }
    default:
        throw SourceError(n.loc, "projection() of this solid is not supported yet (spheres, boxes, cylinders, tori, "
                                 "meshes and straight extrusions are)");
    }
}

std::vector<std::vector<glm::dvec2>> section_loops(const std::vector<Tri>& tris) {
    // A crossing is named by its edge's two end points (sorted), so the two
    // triangles sharing the edge compute the same point bit for bit.
    using Key = std::array<double, 6>;
    std::map<Key, std::uint32_t> ids;
    std::vector<glm::dvec2> points;
    std::vector<std::array<std::uint32_t, 2>> segs;
    std::vector<std::vector<std::uint32_t>> at_point;
    auto crossing = [&](glm::dvec3 p, glm::dvec3 q) {
        if (Key{q.x, q.y, q.z, 0, 0, 0} < Key{p.x, p.y, p.z, 0, 0, 0}) std::swap(p, q);
        const Key k{p.x, p.y, p.z, q.x, q.y, q.z};
        auto [it, fresh] = ids.try_emplace(k, std::uint32_t(points.size()));
        if (fresh) {
            const double t = p.z / (p.z - q.z);
            points.push_back(glm::dvec2(p) + t * (glm::dvec2(q) - glm::dvec2(p)));
            at_point.emplace_back();
        }
        return it->second;
    };
    for (const Tri& t : tris) {
        const glm::dvec3 v[3] = {t.a, t.b, t.c};
        std::uint32_t found[2];
        int count = 0;
        for (int e = 0; e < 3; ++e) {
            const glm::dvec3 p = v[e], q = v[(e + 1) % 3];
            if ((p.z >= 0) != (q.z >= 0) && count < 2) found[count++] = crossing(p, q);
        }
        if (count != 2 || found[0] == found[1]) continue;
        const auto s = std::uint32_t(segs.size());
        segs.push_back({found[0], found[1]});
        at_point[found[0]].push_back(s);
        at_point[found[1]].push_back(s);
    }
    std::vector<bool> used(segs.size(), false);
    std::vector<std::vector<glm::dvec2>> loops;
    for (std::uint32_t s0 = 0; s0 < segs.size(); ++s0) {
        if (used[s0]) continue;
        used[s0] = true;
        std::vector<glm::dvec2> loop{points[segs[s0][0]]};
        std::uint32_t cur = segs[s0][1];
        for (;;) {
            if (cur == segs[s0][0]) break;
            loop.push_back(points[cur]);
            std::uint32_t next = kEmpty;
            for (std::uint32_t s : at_point[cur])
                if (!used[s]) {
                    next = s;
                    break;
                }
            if (next == kEmpty) break;  // an open surface: the loop is closed by its first point
            used[next] = true;
            cur = segs[next][0] == cur ? segs[next][1] : segs[next][0];
        }
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

csg::Polygon2 loops_polygon(const std::vector<std::vector<glm::dvec2>>& loops) {
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    poly.hi = -poly.lo;
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const glm::dvec2 p = loop[i], q = loop[(i + 1) % loop.size()];
            if (p != q) poly.edges.emplace_back(p.x, p.y, q.x, q.y);
            poly.lo = glm::min(poly.lo, p);
            poly.hi = glm::max(poly.hi, p);
        }
    return poly;
}

std::uint32_t prism_node(GraphBuilder& g, const std::vector<std::vector<glm::dvec2>>& loops, const SourceLoc& loc) {
    csg::Polygon2 poly = loops_polygon(loops);
    if (poly.edges.empty()) return kEmpty;
    g.graph.polygons.push_back(std::move(poly));
    graph::Node n;
    n.kind = graph::NodeKind::Primitive;
    n.prim = P::Prism;
    n.p[1] = 1;
    n.index = std::uint32_t(g.graph.polygons.size() - 1);
    n.loc = loc;
    n.flat = true;
    return g.add(std::move(n));
}

std::uint32_t op_node(GraphBuilder& g, graph::NodeKind kind, const std::vector<std::uint32_t>& children,
                      const SourceLoc& loc, std::uint32_t index) {
    graph::Node n;
    n.kind = kind;
    n.index = index;
    n.first_child = std::uint32_t(g.graph.child_refs.size());
    n.child_count = std::uint32_t(children.size());
    n.loc = loc;
    n.flat = true;
    g.add_child_refs(children.data(), children.size());
    return g.add(std::move(n));
}

std::uint32_t mapped(GraphBuilder& g, std::uint32_t child, const glm::dmat2& A, glm::dvec2 t, const SourceLoc& loc) {
    glm::dmat4 m(1.0);
    m[0][0] = A[0][0], m[0][1] = A[0][1], m[1][0] = A[1][0], m[1][1] = A[1][1];
    m[3][0] = t.x, m[3][1] = t.y;
    g.add_matrix(m);
    return op_node(g, graph::NodeKind::Transform, {child}, loc, std::uint32_t(g.graph.matrices.size() - 1));
}

std::uint32_t ellipse_node(GraphBuilder& g, double r, const glm::dmat2& A, glm::dvec2 t, const SourceLoc& loc) {
    graph::Node n;
    n.kind = graph::NodeKind::Primitive;
    n.prim = P::Cylinder;
    n.p[1] = 1, n.p[2] = n.p[3] = r;
    n.loc = loc;
    n.flat = true;
    return mapped(g, g.add(std::move(n)), A, t, loc);
}

}  // namespace kerf::eval::projection
