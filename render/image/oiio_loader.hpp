// Loads the OpenImageIO module (oiio_module/) on first use: beside the kerf
// executable, else where the build put it.
#pragma once
#include <cstddef>

namespace kerf::render {

struct OiioModule {
    int (*can_write)(const char* path) = nullptr;
    int (*write)(const char* path, const void* pixels, int as_float, int width, int height, int channels, int srgb,
                 char* error, std::size_t error_size) = nullptr;
};

// The loaded module; throws ImageWriteError naming the file and dlerror()
// when it cannot be loaded. Thread-safe (loaded once).
const OiioModule& oiio_module();

}  // namespace kerf::render
