// The XML import formats' module, libkerf_xml.so: SVG drawings and AMF
// meshes through libxml2, which brings ICU and liblzma (~0.5 ms of every
// kerf start when kerf linked them); as a module they load on the first
// .svg or .amf import (docs/performance.md, "Start-up"). xml_imports.cpp
// reads the file (and unzips a zipped AMF) and hands the module its bytes.
//
// As the zip module (zip_module.hpp): C entry points on C++ data, built
// with kerf, answering as module_answer.hpp says; the module's other
// symbols are hidden.
#pragma once
#include <string>

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/import/svg.hpp"

namespace kerf::eval {

// kerf_xml_read_amf: the meshes of an AMF file's XML.
using ReadAmfEntry = int (*)(const std::string& bytes, const MeshReading& how, ImportedMesh& out, std::string& error);
// kerf_xml_import_svg: the shapes of an SVG file's XML.
using ImportSvgEntry = int (*)(const std::string& bytes, const SvgOptions& options, SvgDrawing& out,
                               std::string& error);

// The module's readers (amf.cpp, svg.cpp), throwing MeshFormatError and
// MeshLimitError.
namespace mesh_format {
ImportedMesh module_read_amf(const std::string& bytes, const MeshReading& how);
}
SvgDrawing module_import_svg(const std::string& bytes, const SvgOptions& options);

}  // namespace kerf::eval
