// read_amf and import_svg through the XML module (xml_module/xml_module.hpp),
// opened on the first call, so that kerf starts without libxml2, ICU and
// liblzma (docs/performance.md, "Start-up"). The file is read here, with
// the import bounds of MeshFile; the module parses its bytes.
#include <dlfcn.h>

#include <mutex>
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

// The module, loaded once; a failed load is tried again on the next import.
const XmlModule& xml_module() {
    static std::mutex mutex;
    static XmlModule m;
    std::lock_guard<std::mutex> lock(mutex);
    if (m.read_amf) return m;
    std::string why;
    if (void* h = csg::open_module(KERF_XML_MODULE_NAME, KERF_XML_MODULE_PATH, &why)) {
        XmlModule got;
        got.read_amf = reinterpret_cast<ReadAmfEntry>(::dlsym(h, "kerf_xml_read_amf"));
        got.import_svg = reinterpret_cast<ImportSvgEntry>(::dlsym(h, "kerf_xml_import_svg"));
        if (got.read_amf && got.import_svg) return m = got;
        why = "it lacks kerf_xml_read_amf";
    }
    throw MeshFormatError(csg::module_error("SVG and AMF", KERF_XML_MODULE_NAME, why));
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
