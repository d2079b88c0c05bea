// read_amf and import_svg through the XML module (xml_module/xml_module.hpp),
// opened on the first call, so that kerf starts without libxml2, ICU and
// liblzma (docs/performance.md, "Start-up"). The file is read here, with
// the import bounds of MeshFile; the module parses its bytes.
#include <string>

#include "csg/modules.hpp"
#include "interpreter/import/formats.hpp"
#include "interpreter/import/module_answer.hpp"
#include "interpreter/import/xml_module/xml_module.hpp"

namespace kerf::eval {

namespace {

struct XmlModule {
    ReadAmfEntry read_amf = nullptr;
    ImportSvgEntry import_svg = nullptr;
};

XmlModule load_xml_module() {
    std::string why;
    if (void* h = csg::open_module(KERF_XML_MODULE_NAME, KERF_XML_MODULE_PATH, &why)) {
        why.clear();
        const XmlModule m{csg::module_entry<ReadAmfEntry>(h, "kerf_xml_read_amf", &why),
                          csg::module_entry<ImportSvgEntry>(h, "kerf_xml_import_svg", &why)};
        if (why.empty()) return m;
    }
    throw MeshFormatError(csg::module_error("SVG and AMF", KERF_XML_MODULE_NAME, why));
}

// The module, loaded once (a failed load throws and is tried again on the next import).
const XmlModule& xml_module() {
    static const XmlModule m = load_xml_module();
    return m;
}

}  // namespace

namespace mesh_format {

ImportedMesh read_amf(const MeshFile& file, const std::string& path, const MeshReading& how) {
    std::string bytes = file.read_all();
    if (bytes.substr(0, 4) == std::string_view("PK\x03\x04", 4)) bytes = unzip_amf(path);
    ImportedMesh out;
    std::string error;
    rethrow_import(xml_module().read_amf(bytes, how, out, error), error);
    return out;
}

}  // namespace mesh_format

SvgDrawing import_svg(const std::string& path, const SvgOptions& options) {
    const std::string bytes = mesh_format::MeshFile(path).read_all();
    SvgDrawing out;
    std::string error;
    rethrow_import(xml_module().import_svg(bytes, options, out, error), error);
    return out;
}

}  // namespace kerf::eval
