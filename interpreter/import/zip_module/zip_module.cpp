// The module's entry points (zip_module.hpp): the readers' exceptions
// turned into a status and a message.
#include <exception>
#include <string>

#include "interpreter/import/zip_module/zip_module.hpp"

namespace {

using namespace kerf::eval;
using namespace kerf::eval::mesh_format;

template <class F>
int answer(std::string& error, F read) {
    try {
        read();
        return kZipOk;
    } catch (const MeshLimitError& e) {
        error = e.what();
        return kZipLimitError;
    } catch (const std::exception& e) {
        error = e.what();
        return kZipFormatError;
    }
}

}  // namespace

extern "C" {

int kerf_zip_read_3mf(const std::string& path, const MeshReading& how, ImportedMesh& out, std::string& error) {
    return answer(error, [&] { out = lib3mf_read(path, how); });
}

int kerf_zip_unzip_amf(const std::string& path, std::string& out, std::string& error) {
    return answer(error, [&] { out = libzip_unzip_amf(path); });
}
}
