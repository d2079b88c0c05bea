#include "lower/mesh_lowering.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace kerf {

namespace {

// Twice the signed area of the corner (a, b, c) in the face's plane.
double turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Appends the triangles of one polygon face, each in the face's own order
// (corner indices into `points`). A fan around corner 0 is right only for a
// convex face; a concave one (an L-shaped end of an imported OFF, a
// polyhedron's notched face) is cut into ears in the plane of its Newell
// normal, so the triangles cover exactly the polygon — a fan would fold
// over the notch and add crossings outside the face. A face that is not
// planar is cut the same way in that plane (OpenSCAD tessellates such faces
// by their projection too; its triangles may differ).
void triangulate(const std::vector<glm::dvec3>& points, const std::vector<std::uint32_t>& face,
                 std::vector<std::array<std::uint32_t, 3>>& out) {
    const std::size_t n = face.size();
    glm::dvec3 normal(0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 a = points[face[i]], b = points[face[(i + 1) % n]];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    // Drop the normal's largest axis; the other two, in an order that keeps
    // the face counter-clockwise in the plane.
    const glm::dvec3 m = glm::abs(normal);
    const int k = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    int u = (k + 1) % 3, v = (k + 2) % 3;
    if (normal[k] < 0) std::swap(u, v);
    std::vector<glm::dvec2> p(n);
    bool convex = true;
    for (std::size_t i = 0; i < n; ++i) p[i] = {points[face[i]][u], points[face[i]][v]};
    for (std::size_t i = 0; i < n && convex; ++i) convex = turn(p[i], p[(i + 1) % n], p[(i + 2) % n]) >= 0;
    if (convex) {
        for (std::size_t i = 1; i + 1 < n; ++i) out.push_back({face[0], face[i], face[i + 1]});
        return;
    }
    // Ear clipping, O(n²): a corner turning left whose triangle holds no
    // other remaining corner is cut off. Degenerate rests (no such corner:
    // collinear or repeated points) end as a fan.
    std::vector<std::size_t> left(n);
    for (std::size_t i = 0; i < n; ++i) left[i] = i;
    std::size_t i = 0, tried = 0;
    while (left.size() > 3 && tried < left.size()) {
        const std::size_t r = left.size();
        const std::size_t ia = left[(i + r - 1) % r], ib = left[i % r], ic = left[(i + 1) % r];
        bool ear = turn(p[ia], p[ib], p[ic]) > 0;
        for (std::size_t j = 0; j < r && ear; ++j) {
            const std::size_t q = left[j];
            if (q == ia || q == ib || q == ic || p[q] == p[ia] || p[q] == p[ib] || p[q] == p[ic]) continue;
            ear = !(turn(p[ia], p[ib], p[q]) >= 0 && turn(p[ib], p[ic], p[q]) >= 0 && turn(p[ic], p[ia], p[q]) >= 0);
        }
        if (!ear) {
            i = (i + 1) % r;
            ++tried;
            continue;
        }
        out.push_back({face[ia], face[ib], face[ic]});
        left.erase(left.begin() + static_cast<std::ptrdiff_t>(i % r));
        i = (i % r + left.size() - 1) % left.size();
        tried = 0;
    }
    for (std::size_t j = 1; j + 1 < left.size(); ++j) out.push_back({face[left[0]], face[left[j]], face[left[j + 1]]});
}

}  // namespace

csg::Mesh lower_mesh(const graph::PolygonMesh& mesh) {
    csg::Mesh out;
    out.points = mesh.points;
    out.solid = mesh.solid;
    const std::size_t n = mesh.points.size();
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (const auto& face : mesh.faces) {
        if (face.size() < 3) continue;
        bool ok = true;
        for (std::uint32_t v : face) ok = ok && v < n;
        if (!ok) continue;
        tris.clear();
        if (face.size() == 3) tris.push_back({face[0], face[1], face[2]});
        else triangulate(mesh.points, face, tris);
        // Each triangle reversed: OpenSCAD's clockwise order → outward (CCW).
        for (const auto& t : tris) {
            out.triangles.push_back(t[0]);
            out.triangles.push_back(t[2]);
            out.triangles.push_back(t[1]);
        }
    }
    return out;
}

csg::Aabb mesh_bounds(const std::vector<glm::dvec3>& points, const csg::Affine& world_from_object) {
    csg::Aabb box;
    for (const glm::dvec3& p : points) box.extend(world_from_object.point(p));
    return box;
}

}  // namespace kerf
