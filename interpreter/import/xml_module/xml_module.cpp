// The XML module's entry points (xml_module.hpp).
#include <string>

#include "interpreter/import/module_answer.hpp"
#include "interpreter/import/xml_module/xml_module.hpp"

using namespace kerf::eval;

KERF_MODULE_EXPORT int kerf_xml_read_amf(const std::string& bytes, const MeshReading& how, ImportedMesh& out,
                                         std::string& error) {
    return answer_import(error, [&] { out = mesh_format::module_read_amf(bytes, how); });
}

KERF_MODULE_EXPORT int kerf_xml_import_svg(const std::string& bytes, const SvgOptions& options, SvgDrawing& out,
                                           std::string& error) {
    return answer_import(error, [&] { out = module_import_svg(bytes, options); });
}
