// The only code that links OpenImageIO: a module kerf loads with dlopen when
// an image format other than PNG is asked for, so that PNG renders never
// load OpenImageIO's ~260 shared libraries. A C interface keeps the two
// sides independent of each other's C++ types.
#include <cstdio>
#include <string>

#include <OpenImageIO/imageio.h>

namespace {

void set_error(char* error, std::size_t size, const std::string& message) {
    if (size) std::snprintf(error, size, "%s", message.c_str());
}

}  // namespace

extern "C" {

// 1 when OpenImageIO has a writer for this file name's extension.
int kerf_oiio_can_write(const char* path) { return OIIO::ImageOutput::create(path) ? 1 : 0; }

// Writes `pixels`: floats stored as float (`as_float`), else bytes already
// encoded for an 8-bit file. Returns 1, or 0 with `error` filled.
int kerf_oiio_write(const char* path, const void* pixels, int as_float, int width, int height, int channels,
                    int srgb, char* error, std::size_t error_size) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        set_error(error, error_size, "unknown image format");
        return 0;
    }
    const OIIO::TypeDesc type = as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, channels, type);
    if (srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    bool ok = out->open(path, spec) && out->write_image(type, pixels);
    ok = out->close() && ok;
    if (!ok) {
        std::string message = out->geterror();
        set_error(error, error_size, message.empty() ? "write failed" : message);
    }
    return ok ? 1 : 0;
}
}
