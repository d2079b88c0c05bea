// Scene-graph meshes become renderer meshes: polygons fanned into triangles
// and OpenSCAD's clockwise-from-outside order turned into the renderer's
// counter-clockwise (outward) winding.
#pragma once
#include "interpreter/scene_graph.hpp"
#include "csg/scene.hpp"

namespace kerf {

// Faces with fewer than 3 corners or out-of-range indices are skipped (the
// interpreter validates polyhedra; this only keeps the renderer safe).
csg::Mesh lower_mesh(const graph::PolygonMesh& mesh);

// Exact world box of a mesh under an affine map: the box of its mapped points.
csg::Aabb mesh_bounds(const std::vector<glm::dvec3>& points, const csg::Affine& world_from_object);

}  // namespace kerf
