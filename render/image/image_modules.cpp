#include "render/image/image_modules.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <string>

#include "render/image/image.hpp"

namespace kerf::render {

namespace {

// `name` beside the running executable, else at `built` (the build tree);
// its functions are `prefix`_can_write, _encode and _read.
ImageModule load(const char* name, const char* built, const std::string& prefix, const char* what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    std::string why;
    for (const fs::path& p : {ec ? fs::path() : exe.parent_path() / name, fs::path(built)}) {
        if (p.empty() || !fs::exists(p, ec)) continue;
        void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char* e = ::dlerror();
            why = e ? e : "dlopen failed";
            continue;
        }
        ImageModule m;
        m.can_write = reinterpret_cast<decltype(m.can_write)>(::dlsym(h, (prefix + "_can_write").c_str()));
        m.encode = reinterpret_cast<decltype(m.encode)>(::dlsym(h, (prefix + "_encode").c_str()));
        m.read = reinterpret_cast<decltype(m.read)>(::dlsym(h, (prefix + "_read").c_str()));
        if (m.can_write && m.encode && m.read) return m;
        why = p.string() + " lacks " + prefix + "_encode";
    }
    throw ImageWriteError("cannot load the " + std::string(what) + " module " + name +
                          (why.empty() ? " (not beside kerf nor at " + std::string(built) + ")" : ": " + why));
}

}  // namespace

bool codec_extension(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".jpg" || ext == ".jpeg";
}

const ImageModule& image_module(const std::string& ext) {
    if (codec_extension(ext)) {
        static const ImageModule m = load(KERF_CODEC_MODULE_NAME, KERF_CODEC_MODULE_PATH, "kerf_codec", "image codec");
        return m;
    }
    static const ImageModule m = load(KERF_OIIO_MODULE_NAME, KERF_OIIO_MODULE_PATH, "kerf_oiio", "OpenImageIO");
    return m;
}

}  // namespace kerf::render
