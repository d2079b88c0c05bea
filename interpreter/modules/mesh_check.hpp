// Meshes as they come from polyhedron() and import() are often wound
// inconsistently (one face turned, or every face reversed, as many STL and
// OBJ exporters write them) or not closed. The renderer pairs crossings into
// spans by orientation, so such a mesh would silently lose faces or draw
// nothing. check_mesh() makes every closed part consistently oriented and
// outward, and says what it changed and what it could not fix, so the
// caller can warn and fall back to a thin shell.
#pragma once
#include <cstddef>

#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

struct MeshCheck {
    std::size_t faces = 0;               // faces with at least 3 distinct corners
    std::size_t faces_turned = 0;        // reversed to agree with their neighbours and face outward
    std::size_t open_edges = 0;          // edges of one face only (a hole)
    std::size_t nonmanifold_edges = 0;   // edges shared by more than two faces
    bool nonorientable = false;          // no consistent orientation exists (a Möbius band)
    bool closed() const { return open_edges == 0 && nonmanifold_edges == 0 && !nonorientable; }
};

// Corners at bitwise equal positions are one vertex (a triangle soup from
// STL has its own three points per triangle). Faces across an edge used by
// exactly two faces are made to run it in opposite directions; then each
// connected part that is closed is turned so that its signed volume has
// OpenSCAD's sign (faces clockwise seen from outside). `mesh` keeps its
// points; only the order of face corners changes.
MeshCheck check_mesh(graph::PolygonMesh& mesh);

}  // namespace kerf::eval
