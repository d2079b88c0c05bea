// import("file.stl" | "file.obj" | "file.ply"): reading triangle meshes from
// files. The formats store faces counter-clockwise seen from outside; the
// result is in graph::PolygonMesh's OpenSCAD order (clockwise), like polyhedron().
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

// What is wrong with a mesh file, located inside it ("line 12: ..." or
// "byte 84: ..."); the caller prefixes the import statement's location.
struct MeshFormatError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads the file by its extension (case-insensitive). Faces above max_faces
// are an error, so a huge file cannot exhaust memory; every face has at least
// 3 corners, every index is in range, every point is finite.
graph::PolygonMesh import_mesh(const std::string& path, std::uint64_t max_faces);

}  // namespace kerf::eval
