// The image modules, each loaded with dlopen on first use (beside the kerf
// executable, else where the build put it), so that a PNG render loads
// neither: `libkerf_codecs.so` (codec_module/: EXR, TIFF, JPEG through
// OpenEXR, libtiff and libjpeg, ~3 ms to load) and `libkerf_oiio.so`
// (oiio_module/: every other format through OpenImageIO, ~0.6 s and
// ~120 MB to load; docs/performance.md, "Image formats").
#pragma once
#include <cstddef>
#include <string>

namespace kerf::render {

// A module's C interface (codec_module.cpp, oiio_module.cpp): `encode`
// hands the encoded file to `sink` and never writes `path` itself.
struct ImageModule {
    using Sink = void (*)(void* context, const void* bytes, std::size_t size);
    int (*can_write)(const char* path) = nullptr;
    int (*encode)(const char* path, const void* pixels, int as_float, int width, int height, int channels, int srgb,
                  Sink sink, void* context, char* error, std::size_t error_size) = nullptr;
    // Reads an image as linear-or-encoded RGB floats (kerf_oiio_read).
    using PixelSink = void (*)(void* context, const float* rgb, int width, int height);
    int (*read)(const char* path, PixelSink sink, void* context, int* encoded, char* error, std::size_t error_size) = nullptr;
};

// Whether the light codec module handles this (lower-case) extension:
// .exr, .tif, .tiff, .jpg, .jpeg.
bool codec_extension(const std::string& ext);

// The module for a file of that (lower-case) extension: the codec module
// for codec_extension(), else OpenImageIO's. Throws ImageWriteError naming
// the module and dlerror() when it cannot be loaded. Thread-safe (each is
// loaded once; a failed load is retried next call).
const ImageModule& image_module(const std::string& ext);

}  // namespace kerf::render
