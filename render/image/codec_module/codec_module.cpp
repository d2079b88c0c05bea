// The light image module, libkerf_codecs.so: EXR, TIFF and JPEG through
// their own libraries (codecs.hpp), loaded with dlopen only when one of
// those formats is written or read. OpenImageIO (oiio_module/) did this
// before at a cost of ~0.6 s and ~120 MB per run (its ~260 libraries);
// these three libraries load in ~3 ms (docs/performance.md, "Image
// formats"). The C interface is the OpenImageIO module's, so the loader
// and writer treat both alike.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

#include "render/image/codec_module/codecs.hpp"

namespace {

using namespace kerf::codec;

void set_error(char* error, std::size_t size, const std::string& message) {
    if (size) std::snprintf(error, size, "%s", message.c_str());
}

enum class Format { None, Exr, Tiff, Jpeg };

Format format_of(const char* path) {
    std::string p(path);
    const std::size_t dot = p.find_last_of("./");
    if (dot == std::string::npos || p[dot] != '.') return Format::None;
    std::string ext = p.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".exr") return Format::Exr;
    if (ext == ".tif" || ext == ".tiff") return Format::Tiff;
    if (ext == ".jpg" || ext == ".jpeg") return Format::Jpeg;
    return Format::None;
}

}  // namespace

extern "C" {

using Sink = void (*)(void* context, const void* bytes, std::size_t size);
using PixelSink = void (*)(void* context, const float* rgb, int width, int height);

// 1 for the formats this module writes (and reads).
int kerf_codec_can_write(const char* path) { return format_of(path) != Format::None ? 1 : 0; }

// As kerf_oiio_encode: `pixels` floats (`as_float`) or 8-bit codes, encoded
// into memory and handed to `sink` once; nothing is written to `path`.
int kerf_codec_encode(const char* path, const void* pixels, int as_float, int width, int height, int channels,
                      int /*srgb*/, Sink sink, void* context, char* error, std::size_t error_size) {
    Bytes out;
    std::string why;
    switch (format_of(path)) {
        case Format::Exr:
            why = as_float ? encode_exr(static_cast<const float*>(pixels), width, height, channels, out)
                           : "EXR holds floats, the image is 8-bit";
            break;
        case Format::Tiff: why = encode_tiff(pixels, as_float != 0, width, height, channels, out); break;
        case Format::Jpeg:
            why = as_float ? "JPEG holds 8-bit codes, the image is float"
                           : encode_jpeg(static_cast<const std::uint8_t*>(pixels), width, height, channels, out);
            break;
        case Format::None: why = "unknown image format"; break;
    }
    if (why.empty() && out.empty()) why = "the encoder produced no bytes";
    if (!why.empty()) {
        set_error(error, error_size, why);
        return 0;
    }
    sink(context, out.data(), out.size());
    return 1;
}

// As kerf_oiio_read: RGB floats, `*encoded` 1 for integer files (sRGB), 0 for floats.
int kerf_codec_read(const char* path, PixelSink sink, void* context, int* encoded, char* error, std::size_t error_size) {
    Pixels px;
    std::string why;
    switch (format_of(path)) {
        case Format::Exr: why = read_exr(path, px); break;
        case Format::Tiff: why = read_tiff(path, px); break;
        case Format::Jpeg: why = read_jpeg(path, px); break;
        case Format::None: why = "unknown image format"; break;
    }
    if (!why.empty()) {
        set_error(error, error_size, why);
        return 0;
    }
    *encoded = px.encoded ? 1 : 0;
    sink(context, px.rgb.data(), px.width, px.height);
    return 1;
}
}
