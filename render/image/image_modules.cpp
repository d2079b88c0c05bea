#include "render/image/image_modules.hpp"

#include <dlfcn.h>

#include <string>

#include "csg/modules.hpp"
#include "render/image/image.hpp"

namespace kerf::render {

namespace {

// The module `name` (csg/modules.hpp); its functions are `prefix`_can_write,
// _encode and _read.
ImageModule load(const char* name, const char* built, const std::string& prefix, const char* what) {
    std::string why;
    if (void* h = csg::open_module(name, built, &why)) {
        ImageModule m;
        m.can_write = reinterpret_cast<decltype(m.can_write)>(::dlsym(h, (prefix + "_can_write").c_str()));
        m.encode = reinterpret_cast<decltype(m.encode)>(::dlsym(h, (prefix + "_encode").c_str()));
        m.read = reinterpret_cast<decltype(m.read)>(::dlsym(h, (prefix + "_read").c_str()));
        if (m.can_write && m.encode && m.read) return m;
        why = "it lacks " + prefix + "_encode";
    }
    throw ImageWriteError(csg::module_error(what, name, why));
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
