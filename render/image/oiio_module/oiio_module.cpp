// The only code that links OpenImageIO: a module kerf loads with dlopen when
// an image format other than PNG, PFM, EXR, TIFF and JPEG is asked for
// (those have lighter writers: png_file.cpp, netpbm.cpp, codec_module/), so
// that their renders never load OpenImageIO's ~260 shared libraries. A C interface keeps the two
// sides independent of each other's C++ types.
//
// It never writes a file. The writers' own file handling is where disk-full
// went unnoticed (BMP, Targa and JPEG 2000 ignore failed writes; libjpeg
// calls exit()), so each image is encoded into memory and handed to kerf,
// which writes it with checked calls (replace_file.cpp).
#include <cstdio>
#include <string>
#include <vector>

#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace {

void set_error(char* error, std::size_t size, const std::string& message) {
    if (size) std::snprintf(error, size, "%s", message.c_str());
}

// open, write, close, with every failure turned into `why`. Some writers
// report a failure yet return success (JPEG 2000 below 32 pixels: a 77-byte
// file that does not read back), so a pending error counts too.
bool encode(OIIO::ImageOutput& out, const std::string& name, const OIIO::ImageSpec& spec, const void* pixels,
            std::string& why) {
    bool ok = out.open(name, spec) && out.write_image(spec.format, pixels) && !out.has_error();
    if (!ok) why = out.geterror();
    // close() finishes some formats (TIFF directories, EXR tables): its
    // result counts, but what it leaves in geterror() without failing is a
    // warning (TIFF's Exif directory), not an error.
    if (!out.close() && ok) {
        ok = false;
        why = out.geterror();
    }
    if (!ok && why.empty()) why = "write failed";
    return ok;
}

using Sink = void (*)(void* context, const void* bytes, std::size_t size);

// Writers without IOProxy support (SGI, ICO, FITS, RLA, HEIF, ...) open the
// file by name themselves: they get a memory file, /proc/self/fd/N.
bool encode_to_memfd(OIIO::ImageOutput& out, OIIO::ImageSpec spec, const std::string& path, const void* pixels,
                     Sink sink, void* context, std::string& why) {
    const int fd = ::memfd_create("kerf-image", MFD_CLOEXEC);
    if (fd < 0) {
        why = "cannot create a memory file for the encoder";
        return false;
    }
    // The HEIF writer picks AV1 by the file name's extension, which the
    // memory file's name lacks.
    if (std::string(out.format_name()) == "heif" && OIIO::Filesystem::extension(path) == ".avif" &&
        spec.get_string_attribute("compression").empty())
        spec.attribute("compression", "avif");
    bool ok = encode(out, "/proc/self/fd/" + std::to_string(fd), spec, pixels, why);
    struct stat st {};
    void* bytes = MAP_FAILED;
    if (ok && ::fstat(fd, &st) == 0 && st.st_size > 0)
        bytes = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_SHARED, fd, 0);
    if (ok && bytes == MAP_FAILED) {
        ok = false;
        why = "cannot read the encoded image back from memory";
    }
    if (ok) {
        sink(context, bytes, static_cast<std::size_t>(st.st_size));
        ::munmap(bytes, static_cast<std::size_t>(st.st_size));
    }
    ::close(fd);
    return ok;
}

}  // namespace

extern "C" {

using PixelSink = void (*)(void* context, const float* rgb, int width, int height);

// Reads the first subimage of `path` as 3-channel floats, rows top to
// bottom, grey replicated and channels past the third dropped (alpha is
// not a colour). `*encoded` is 1 when the file stores integers, which kerf
// takes as sRGB-encoded, 0 for float formats (EXR, PFM, float TIFF): linear.
// On success `sink` gets the pixels and 1 is returned, else 0 with `error`.
int kerf_oiio_read(const char* path, PixelSink sink, void* context, int* encoded, char* error, std::size_t error_size) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::string why = OIIO::geterror();
        set_error(error, error_size, why.empty() ? "cannot open the image" : why);
        return 0;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int w = spec.width, h = spec.height, n = spec.nchannels;
    if (w <= 0 || h <= 0 || n <= 0 || std::size_t(w) * std::size_t(h) > (std::size_t(1) << 28)) {
        set_error(error, error_size, "image has no pixels or more than 2^28");
        return 0;
    }
    std::vector<float> all(std::size_t(w) * h * n);
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, all.data())) {
        set_error(error, error_size, in->geterror());
        return 0;
    }
    std::vector<float> rgb(std::size_t(w) * h * 3);
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = all[i * n + (n >= 3 ? c : 0)];
    *encoded = spec.format.is_floating_point() ? 0 : 1;
    sink(context, rgb.data(), w, h);
    return 1;
}

// 1 when OpenImageIO has a writer for this file name's extension.
int kerf_oiio_can_write(const char* path) { return OIIO::ImageOutput::create(path) ? 1 : 0; }

// Encodes `pixels` in the format `path`'s extension names, into memory:
// floats stored as float (`as_float`), else bytes already encoded for an
// 8-bit file. Nothing is written to `path`; on success `sink` is called once
// with the whole file's bytes and 1 is returned, else 0 with `error` filled.
int kerf_oiio_encode(const char* path, const void* pixels, int as_float, int width, int height, int channels,
                     int srgb, Sink sink, void* context, char* error, std::size_t error_size) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        set_error(error, error_size, "unknown image format");
        return 0;
    }
    OIIO::ImageSpec spec(width, height, channels, as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    std::string why;
    bool ok = false;
    if (out->supports("ioproxy")) {
        OIIO::Filesystem::IOVecOutput memory;
        // With a proxy the writer uses `path` only for its extension.
        ok = out->set_ioproxy(&memory) && encode(*out, path, spec, pixels, why);
        if (!ok && why.empty()) why = out->geterror();
        if (ok) sink(context, memory.buffer().data(), memory.buffer().size());
    } else {
        ok = encode_to_memfd(*out, spec, path, pixels, sink, context, why);
    }
    if (!ok) set_error(error, error_size, why.empty() ? "write failed" : why);
    return ok ? 1 : 0;
}
}
