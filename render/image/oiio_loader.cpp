#include "render/image/oiio_loader.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <string>

#include "render/image/image.hpp"

namespace kerf::render {

namespace {

OiioModule load() {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    std::string tried, why;
    for (const fs::path& p : {ec ? fs::path() : exe.parent_path() / KERF_OIIO_MODULE_NAME, fs::path(KERF_OIIO_MODULE_PATH)}) {
        if (p.empty() || !fs::exists(p, ec)) continue;
        void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char* e = ::dlerror();
            why = e ? e : "dlopen failed";
            continue;
        }
        OiioModule m;
        m.can_write = reinterpret_cast<decltype(m.can_write)>(::dlsym(h, "kerf_oiio_can_write"));
        m.encode = reinterpret_cast<decltype(m.encode)>(::dlsym(h, "kerf_oiio_encode"));
        m.read = reinterpret_cast<decltype(m.read)>(::dlsym(h, "kerf_oiio_read"));
        if (m.can_write && m.encode && m.read) return m;
        why = p.string() + " lacks kerf_oiio_encode";
    }
    throw ImageWriteError("cannot load the OpenImageIO module " + std::string(KERF_OIIO_MODULE_NAME) +
                          (why.empty() ? " (not beside kerf nor at " KERF_OIIO_MODULE_PATH ")" : ": " + why));
}

}  // namespace

const OiioModule& oiio_module() {
    static const OiioModule m = load();  // a failed load throws and is retried next call
    return m;
}

}  // namespace kerf::render
