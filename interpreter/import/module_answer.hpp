// What the import modules' entry points answer (zip_module/, xml_module/):
// the exception a reader threw, as a status and a message, so that no
// exception crosses a module's boundary; and that answer thrown again on
// kerf's side (zip_imports.cpp, xml_imports.cpp).
#pragma once
#include <exception>
#include <string>

#include "interpreter/import/mesh_import.hpp"

// An entry point of a module: C linkage, visible (the rest is hidden).
#define KERF_MODULE_EXPORT extern "C" __attribute__((visibility("default")))

namespace kerf::eval {

enum ImportStatus : int { kImportOk = 0, kImportFormatError = 1, kImportLimitError = 2 };

// Runs `read` and answers how it went, its message in `error`.
template <class F>
int answer_import(std::string& error, F read) {
    try {
        read();
        return kImportOk;
    } catch (const MeshLimitError& e) {
        error = e.what();
        return kImportLimitError;
    } catch (const std::exception& e) {
        error = e.what();
        return kImportFormatError;
    }
}

// The answer as the exception the module's reader threw.
inline void rethrow_import(int status, const std::string& error) {
    if (status == kImportLimitError) throw MeshLimitError(error);
    if (status != kImportOk) throw MeshFormatError(error);
}

}  // namespace kerf::eval
