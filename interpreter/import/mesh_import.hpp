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

// The longest file import() reads: the bound scene files have
// (kMaxSourceBytes). A binary STL of this size holds 5.4 million triangles.
constexpr std::uint64_t kMaxImportBytes = std::uint64_t(256) << 20;

// Reads the file by its extension (case-insensitive). A file longer than
// kMaxImportBytes, counts in a header that the file's size cannot hold, and
// faces above max_faces are errors found before the data is read, so a huge
// or lying file cannot exhaust memory; every face has at least 3 corners,
// every index is in range, every point is finite.
graph::PolygonMesh import_mesh(const std::string& path, std::uint64_t max_faces);

}  // namespace kerf::eval
