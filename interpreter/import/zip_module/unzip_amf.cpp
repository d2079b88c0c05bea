// The XML of a compressed AMF file, read with libzip.
#include <filesystem>
#include <memory>

#include <zip.h>

#include "interpreter/import/zip_module/zip_module.hpp"

namespace kerf::eval::mesh_format {

// A compressed AMF file is a zip archive holding the XML: the entry named
// like the file, or its only entry (as OpenSCAD 2021.01 looks for it).
std::string libzip_unzip_amf(const std::string& path) {
    int code = 0;
    std::unique_ptr<zip_t, void (*)(zip_t*)> z(zip_open(path.c_str(), ZIP_RDONLY, &code), zip_discard);
    if (!z) {
        zip_error_t e;
        zip_error_init_with_code(&e, code);
        const std::string why = zip_error_strerror(&e);
        zip_error_fini(&e);
        throw MeshFormatError("not a readable compressed AMF file: " + why);
    }
    const std::string name = std::filesystem::path(path).filename().string();
    zip_int64_t at = zip_name_locate(z.get(), name.c_str(), ZIP_FL_NOCASE | ZIP_FL_NODIR);
    if (at < 0 && zip_get_num_entries(z.get(), 0) == 1) at = 0;
    if (at < 0)
        throw MeshFormatError("a compressed AMF file must hold one file or one named '" + name + "', this one holds " +
                              std::to_string(zip_get_num_entries(z.get(), 0)));
    zip_stat_t st;
    if (zip_stat_index(z.get(), static_cast<zip_uint64_t>(at), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
        throw MeshFormatError(std::string("not a readable compressed AMF file: ") + zip_strerror(z.get()));
    if (st.size > kMaxImportBytes)  // a zip bomb is refused before it is inflated
        throw MeshLimitError("the compressed AMF file unpacks to " + std::to_string(st.size) + " bytes, more than " +
                             std::to_string(kMaxImportBytes >> 20) + " MiB, too large to import");
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> f(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(at), 0),
                                                        zip_fclose);
    std::string bytes(static_cast<std::size_t>(st.size), '\0');
    if (!f || zip_fread(f.get(), bytes.data(), st.size) != static_cast<zip_int64_t>(st.size))
        throw MeshFormatError(std::string("not a readable compressed AMF file: ") + zip_strerror(z.get()));
    return bytes;
}

}  // namespace kerf::eval::mesh_format
