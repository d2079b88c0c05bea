// Loads the OpenImageIO module (oiio_module/) on first use: beside the kerf
// executable, else where the build put it.
#pragma once
#include <cstddef>

namespace kerf::render {

// The module's C interface (oiio_module/oiio_module.cpp): `encode` hands
// the encoded file to `sink` and never writes `path` itself.
struct OiioModule {
    using Sink = void (*)(void* context, const void* bytes, std::size_t size);
    int (*can_write)(const char* path) = nullptr;
    int (*encode)(const char* path, const void* pixels, int as_float, int width, int height, int channels, int srgb,
                  Sink sink, void* context, char* error, std::size_t error_size) = nullptr;
    // Reads an image as linear-or-encoded RGB floats (oiio_module.cpp, kerf_oiio_read).
    using PixelSink = void (*)(void* context, const float* rgb, int width, int height);
    int (*read)(const char* path, PixelSink sink, void* context, int* encoded, char* error, std::size_t error_size) = nullptr;
};

// The loaded module; throws ImageWriteError naming the file and dlerror()
// when it cannot be loaded. Thread-safe (loaded once).
const OiioModule& oiio_module();

}  // namespace kerf::render
