// The module's entry points (zip_module.hpp).
#include <string>

#include "interpreter/import/module_answer.hpp"
#include "interpreter/import/zip_module/zip_module.hpp"

using namespace kerf::eval;
using namespace kerf::eval::mesh_format;

KERF_MODULE_EXPORT int kerf_zip_read_3mf(const std::string& path, const MeshReading& how, ImportedMesh& out,
                                         std::string& error) {
    return answer_import(error, [&] { out = lib3mf_read(path, how); });
}

KERF_MODULE_EXPORT int kerf_zip_unzip_amf(const std::string& path, std::string& out, std::string& error) {
    return answer_import(error, [&] { out = libzip_unzip_amf(path); });
}
