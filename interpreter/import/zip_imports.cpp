// read_3mf and unzip_amf through the zip module (zip_module/zip_module.hpp),
// opened on the first call, so that kerf starts without lib3mf, libzip and
// the libcrypto they bring (docs/performance.md, "Start-up").
#include <string>

#include "csg/modules.hpp"
#include "interpreter/import/formats.hpp"
#include "interpreter/import/module_answer.hpp"
#include "interpreter/import/zip_module/zip_module.hpp"

namespace kerf::eval::mesh_format {

namespace {

struct ZipModule {
    Read3mf read_3mf = nullptr;
    UnzipAmf unzip_amf = nullptr;
};

ZipModule load_zip_module() {
    std::string why;
    if (void* h = csg::open_module(KERF_ZIP_MODULE_NAME, KERF_ZIP_MODULE_PATH, &why)) {
        why.clear();
        const ZipModule m{csg::module_entry<Read3mf>(h, "kerf_zip_read_3mf", &why),
                          csg::module_entry<UnzipAmf>(h, "kerf_zip_unzip_amf", &why)};
        if (why.empty()) return m;
    }
    throw MeshFormatError(csg::module_error("3MF and compressed AMF", KERF_ZIP_MODULE_NAME, why));
}

// The module, loaded once (a failed load throws and is tried again on the next import).
const ZipModule& zip_module() {
    static const ZipModule m = load_zip_module();
    return m;
}

}  // namespace

ImportedMesh read_3mf(const std::string& path, const MeshReading& how) {
    ImportedMesh out;
    std::string error;
    rethrow_import(zip_module().read_3mf(path, how, out, error), error);
    return out;
}

std::string unzip_amf(const std::string& path) {
    std::string out, error;
    rethrow_import(zip_module().unzip_amf(path, out, error), error);
    return out;
}

}  // namespace kerf::eval::mesh_format
