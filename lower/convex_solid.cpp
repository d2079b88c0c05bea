#include "lower/convex_solid.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace kerf {

using graph::NodeKind;
using P = csg::PrimKind;

std::uint32_t GraphAppender::add(graph::Node n) {
    g_.nodes.push_back(std::move(n));
    return std::uint32_t(g_.nodes.size() - 1);
}

std::uint32_t GraphAppender::op(NodeKind kind, const std::vector<std::uint32_t>& children, const SourceLoc& loc,
                                std::uint32_t index) {
    graph::Node n;
    n.kind = kind;
    n.index = index;
    n.loc = loc;
    n.first_child = std::uint32_t(g_.child_refs.size());
    n.child_count = std::uint32_t(children.size());
    g_.child_refs.insert(g_.child_refs.end(), children.begin(), children.end());
    return add(std::move(n));
}

std::uint32_t GraphAppender::transform(const glm::dmat4& m, std::uint32_t child, const SourceLoc& loc) {
    g_.matrices.push_back(m);
    return op(NodeKind::Transform, {child}, loc, std::uint32_t(g_.matrices.size() - 1));
}

std::uint32_t GraphAppender::primitive(P kind, std::initializer_list<double> p, const SourceLoc& loc,
                                       std::uint32_t index) {
    graph::Node n;
    n.kind = NodeKind::Primitive;
    n.prim = kind;
    n.index = index;
    n.loc = loc;
    std::size_t i = 0;
    for (double x : p) n.p[i++] = x;
    return add(std::move(n));
}

std::uint32_t GraphAppender::mesh(std::vector<glm::dvec3> points, std::vector<std::vector<std::uint32_t>> ccw_faces,
                                  const SourceLoc& loc) {
    graph::PolygonMesh m;
    m.points = std::move(points);
    for (auto& f : ccw_faces) std::reverse(f.begin(), f.end());  // the graph's order is clockwise
    m.faces = std::move(ccw_faces);
    g_.meshes.push_back(std::move(m));
    return primitive(P::Mesh, {}, loc, std::uint32_t(g_.meshes.size() - 1));
}

namespace {

glm::dmat4 translation(const glm::dvec3& t) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(t, 1);
    return m;
}

class Offsetter {
public:
    Offsetter(GraphAppender& out, double r, const SourceLoc& loc) : out_(out), r_(r), loc_(loc) {}
    std::vector<std::uint32_t> parts;

    // A vertical cylinder of radius r standing on c, `height` tall (a disc's corner).
    void post(const glm::dvec3& c, double height) {
        parts.push_back(out_.transform(translation(c), out_.primitive(P::Cylinder, {0, height, r_, r_}, loc_), loc_));
    }

    void ball(const glm::dvec3& c) { parts.push_back(out_.transform(translation(c), out_.primitive(P::Sphere, {r_}, loc_), loc_)); }

    // The cylinder of radius r around segment a–b (its axis frame right-handed).
    void rod(const glm::dvec3& a, const glm::dvec3& b) {
        const double len = glm::length(b - a);
        if (!(len > 0)) return;
        const glm::dvec3 u = (b - a) / len;
        const glm::dvec3 t = std::abs(u.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 e1 = glm::normalize(glm::cross(t, u)), e2 = glm::cross(u, e1);
        glm::dmat4 m(1.0);
        m[0] = glm::dvec4(e1, 0), m[1] = glm::dvec4(e2, 0), m[2] = glm::dvec4(u, 0), m[3] = glm::dvec4(a, 1);
        parts.push_back(out_.transform(m, out_.primitive(P::Cylinder, {0, len, r_, r_}, loc_), loc_));
    }

    // The convex polygon `loop` (counter-clockwise about d's direction)
    // swept from `base` to `base + d`: a prism mesh.
    void slab(const std::vector<glm::dvec3>& loop, const glm::dvec3& base_shift, const glm::dvec3& d) {
        const std::uint32_t k = std::uint32_t(loop.size());
        std::vector<glm::dvec3> pts;
        for (const glm::dvec3& v : loop) pts.push_back(v + base_shift);
        for (const glm::dvec3& v : loop) pts.push_back(v + base_shift + d);
        std::vector<std::vector<std::uint32_t>> faces;
        std::vector<std::uint32_t> bottom, top;
        for (std::uint32_t i = 0; i < k; ++i) bottom.push_back(k - 1 - i), top.push_back(k + i);
        faces.push_back(bottom);
        faces.push_back(top);
        for (std::uint32_t i = 0; i < k; ++i) {
            const std::uint32_t j = (i + 1) % k;
            faces.push_back({i, j, k + j, k + i});
        }
        parts.push_back(out_.mesh(std::move(pts), std::move(faces), loc_));
    }

private:
    GraphAppender& out_;
    double r_;
    SourceLoc loc_;
};


// hull ⊕ disc: the section (the hull's points seen from above) grown by
// the disc, between the points' lowest and highest z.
std::uint32_t grown_section(GraphAppender& out, const ConvexHull& h, double r, const SourceLoc& loc) {
    double z0 = h.points[0].z, z1 = z0;
    std::vector<glm::dvec3> flat;
    for (const glm::dvec3& p : h.points) z0 = std::min(z0, p.z), z1 = std::max(z1, p.z), flat.push_back({p.x, p.y, 0});
    if (!(z1 > z0)) return out.empty(loc);
    ConvexHull section = convex_hull(flat);
    if (section.dim == 2 && section.normal.z < 0) std::reverse(section.points.begin(), section.points.end());
    std::vector<glm::dvec3> loop;
    for (const glm::dvec3& p : section.points) loop.push_back({p.x, p.y, z0});
    Offsetter o(out, r, loc);
    const glm::dvec3 up(0, 0, z1 - z0);
    if (section.dim == 2) o.slab(loop, glm::dvec3(0), up);
    const std::size_t k = loop.size();
    for (std::size_t i = 0; i < k && section.dim >= 1; ++i) {
        const glm::dvec3 a = loop[i], b = loop[(i + 1) % k];
        const glm::dvec3 n = r * glm::normalize(glm::cross(b - a, glm::dvec3(0, 0, 1)));  // outward: loop is counter-clockwise
        o.slab({a, a + n, b + n, b}, glm::dvec3(0), up);
        if (section.dim == 1) o.slab({b, b - n, a - n, a}, glm::dvec3(0), up);  // a segment: both sides
        if (section.dim == 1) break;
    }
    for (const glm::dvec3& c : loop) o.post(c, z1 - z0);
    return o.parts.size() == 1 ? o.parts[0] : out.op(NodeKind::Union, o.parts, loc);
}

}  // namespace

std::uint32_t convex_solid(GraphAppender& out, ConvexHull h, double r, bool disc, const SourceLoc& loc) {
    if (h.dim < 0 || (r == 0 && h.dim < 3)) return out.empty(loc);
    if (disc && r > 0) return grown_section(out, h, r, loc);
    if (r == 0) return out.mesh(std::move(h.points), std::move(h.faces), loc);
    Offsetter o(out, r, loc);
    for (const glm::dvec3& v : h.points) o.ball(v);
    if (h.dim == 1) o.rod(h.points[0], h.points[1]);
    if (h.dim == 2) {
        for (std::size_t i = 0; i < h.points.size(); ++i) o.rod(h.points[i], h.points[(i + 1) % h.points.size()]);
        o.slab(h.points, -r * h.normal, 2 * r * h.normal);
    }
    if (h.dim == 3) {
        o.parts.push_back(out.mesh(h.points, h.faces, loc));
        std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
        for (std::size_t f = 0; f < h.faces.size(); ++f) {
            const auto& loop = h.faces[f];
            std::vector<glm::dvec3> corners;
            for (std::size_t i = 0; i < loop.size(); ++i) {
                corners.push_back(h.points[loop[i]]);
                const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
                if (edges.insert({std::min(a, b), std::max(a, b)}).second) o.rod(h.points[a], h.points[b]);
            }
            o.slab(corners, glm::dvec3(0), r * h.normals[f]);
        }
    }
    if (o.parts.size() == 1) return o.parts[0];
    return out.op(NodeKind::Union, o.parts, loc);
}

}  // namespace kerf
