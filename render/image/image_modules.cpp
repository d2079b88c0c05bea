#include "render/image/image_modules.hpp"

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
        why.clear();
        const ImageModule m{csg::module_entry<decltype(ImageModule::can_write)>(h, (prefix + "_can_write").c_str(), &why),
                            csg::module_entry<decltype(ImageModule::encode)>(h, (prefix + "_encode").c_str(), &why),
                            csg::module_entry<decltype(ImageModule::read)>(h, (prefix + "_read").c_str(), &why)};
        if (why.empty()) return m;
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
