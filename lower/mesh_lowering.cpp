#include "lower/mesh_lowering.hpp"

namespace kerf {

csg::Mesh lower_mesh(const graph::PolygonMesh& mesh) {
    csg::Mesh out;
    out.points = mesh.points;
    out.solid = mesh.solid;
    const std::size_t n = mesh.points.size();
    for (const auto& face : mesh.faces) {
        if (face.size() < 3) continue;
        bool ok = true;
        for (std::uint32_t v : face) ok = ok && v < n;
        if (!ok) continue;
        // Fan around corner 0, each triangle reversed (c0, c[k+1], c[k]).
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
            out.triangles.push_back(face[0]);
            out.triangles.push_back(face[k + 1]);
            out.triangles.push_back(face[k]);
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
