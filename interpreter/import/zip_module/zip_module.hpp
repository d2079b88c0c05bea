// The zip-based import formats' module, libkerf_zip.so: 3MF through lib3mf
// and compressed AMF through libzip. Both libraries pull in libcrypto
// (libzip's encrypted archives), ~2 ms of every kerf start when kerf linked
// them; as a module they load only when a .3mf or a compressed .amf is
// imported (docs/performance.md, "Start-up"). zip_imports.cpp loads it.
//
// The entry points are C functions (found by dlsym) on C++ data: the
// module is built with kerf, from the same headers, by the same compiler.
// Each answers with a status and a message (module_answer.hpp), so no
// exception crosses the module's boundary.
#pragma once
#include <cstddef>
#include <string>

#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval::mesh_format {

// kerf_zip_read_3mf: the meshes of a 3MF file into `out`.
using Read3mf = int (*)(const std::string& path, const MeshReading& how, ImportedMesh& out, std::string& error);
// kerf_zip_unzip_amf: the XML of a compressed AMF file into `out`.
using UnzipAmf = int (*)(const std::string& path, std::string& out, std::string& error);

// The module's own readers (threemf.cpp, unzip_amf.cpp), throwing
// MeshFormatError and MeshLimitError.
ImportedMesh lib3mf_read(const std::string& path, const MeshReading& how);
std::string libzip_unzip_amf(const std::string& path);

}  // namespace kerf::eval::mesh_format
