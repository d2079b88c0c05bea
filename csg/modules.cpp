#include "csg/modules.hpp"

#include <dlfcn.h>

#include <filesystem>

namespace kerf::csg {

void* open_module(const char* name, const char* built, std::string* why) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    why->clear();
    for (const fs::path& p : {ec ? fs::path() : exe.parent_path() / name, fs::path(built)}) {
        if (p.empty() || !fs::exists(p, ec)) continue;
        if (void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL)) return h;
        const char* e = ::dlerror();
        *why = e ? e : "dlopen failed";
    }
    if (why->empty()) *why = "not beside kerf nor at " + std::string(built);
    return nullptr;
}

void* module_symbol(void* handle, const char* symbol) { return ::dlsym(handle, symbol); }

std::string module_error(const char* what, const char* name, const std::string& why) {
    return "cannot load the " + std::string(what) + " module " + name + ": " + why;
}

}  // namespace kerf::csg
