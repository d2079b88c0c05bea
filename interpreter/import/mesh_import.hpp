// import("file.stl" | ".obj" | ".ply" | ".off" | ".amf" | ".3mf"): reading
// polygon meshes from files. The formats store faces counter-clockwise seen
// from outside; the result is in graph::PolygonMesh's OpenSCAD order
// (clockwise), like polyhedron().
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

// What is wrong with a mesh file, located inside it ("line 12: ..." or
// "byte 84: ..."); the caller prefixes the import statement's location.
struct MeshFormatError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A file beyond one of kerf's bounds (its length, --max-list): an error in
// both dialects, where a broken file is only a warning in .scad.
struct MeshLimitError : MeshFormatError {
    using MeshFormatError::MeshFormatError;
};

// The longest file import() reads: the bound scene files have
// (kMaxSourceBytes). A binary STL of this size holds 5.4 million triangles.
constexpr std::uint64_t kMaxImportBytes = std::uint64_t(256) << 20;

// What a file holds: one mesh, or for AMF and 3MF one per object (or build
// item), to be united as OpenSCAD unites them. Warnings name what was read
// but not used ("<edge>: curved triangles are read flat").
struct ImportedMesh {
    std::vector<graph::PolygonMesh> parts;
    std::vector<std::string> warnings;
};

// How to read: `openscad` takes AMF and 3MF files as OpenSCAD 2021.01 does
// (units ignored, every 3MF mesh object once where it is stored, the build
// not applied: docs/openscad.md), with a warning where that differs from
// what the file says; otherwise the format's own meaning (units scaled to
// millimetres, 3MF build items and components placed).
struct MeshReading {
    std::uint64_t max_faces = 0;  // over all parts
    bool openscad = false;
};

// Reads the file by its extension (case-insensitive). A file longer than
// kMaxImportBytes, counts in a header that the file's size cannot hold, and
// faces above max_faces are errors found before the data is read, so a huge
// or lying file cannot exhaust memory; every part has a face, every face at
// least 3 corners, every index is in range, every point is finite.
ImportedMesh import_mesh(const std::string& path, const MeshReading& how);

}  // namespace kerf::eval
