// Image output: every format is encoded into memory — PNG by libpng
// (png_file.cpp), EXR, TIFF and JPEG by their own libraries and the others
// by OpenImageIO, each in a module loaded only then (image_modules.cpp) — and the bytes are written atomically and checked by
// replace_file(), so readers never see half a file and a failed write
// (a full disk, a signal) keeps the previous image.
#include "render/image/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/image/netpbm.hpp"
#include "render/image/image_modules.hpp"
#include "render/image/png_file.hpp"
#include "render/image/replace_file.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool is_float_format(const std::string& ext) {
    return ext == ".exr" || ext == ".tif" || ext == ".tiff" || ext == ".hdr" || ext == ".pfm";
}

std::uint8_t unit_byte(float v) { return std::uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

// 8-bit files cannot hold linear floats or +inf: encode what the pixels mean
// (docs/spec.md §7: depth normalised to the nearest and farthest hit, misses 0).
BigVector<std::uint8_t> encode_8bit(const Image& im) {
    BigVector<std::uint8_t> out(im.pixels.size());
    switch (im.content) {
        case ImageContent::Color:
            // Millions of channels at 2048²: as long as a small render's tracing.
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), 1 << 16), [&](const auto& r) {
                const SrgbTable& table = srgb_table();
                const float* in = im.pixels.data();
                std::uint8_t* bytes = out.data();
                for (std::size_t i = r.begin(); i < r.end(); ++i) bytes[i] = srgb_byte(table, in[i]);
            });
            // A fourth channel is coverage (--alpha): linear, not sRGB.
            if (im.channels == 4)
                for (std::size_t i = 3; i < out.size(); i += 4) out[i] = unit_byte(im.pixels[i]);
            break;
        case ImageContent::Normal:
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = unit_byte(0.5f * im.pixels[i] + 0.5f);
            break;
        case ImageContent::Depth: {
            float near = std::numeric_limits<float>::infinity(), far = -near;
            for (float v : im.pixels)
                if (std::isfinite(v)) near = std::min(near, v), far = std::max(far, v);
            const float range = far > near ? far - near : 1.0f;
            // Nearest hit white, farthest still visibly grey, misses black.
            for (std::size_t i = 0; i < out.size(); ++i)
                out[i] = std::isfinite(im.pixels[i]) ? unit_byte(1.0f - 0.8f * (im.pixels[i] - near) / range) : 0;
            break;
        }
        case ImageContent::Hits: {
            float most = 0;
            for (float v : im.pixels) most = std::max(most, v);
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = most > 0 ? unit_byte(im.pixels[i] / most) : 0;
            break;
        }
    }
    return out;
}

// OpenJPEG codes 6 resolution levels, which need 2^5 pixels each way; below
// that its writer reported success over a 77-byte file that reads back as
// nothing. 0 x 0: the size is not known yet.
void check_size(const std::string& path, const std::string& ext, int width, int height) {
    constexpr int kSide = 32;
    if ((ext == ".jp2" || ext == ".j2k") && width > 0 && height > 0 && (width < kSide || height < kSide))
        throw ImageWriteError("cannot write " + path + ": JPEG 2000 needs at least 32x32 pixels (OpenJPEG's 6 " +
                              "resolution levels), the image is " + std::to_string(width) + "x" +
                              std::to_string(height));
}

// Identity, not spelling: "./a.png", a symlink or a hard link to the input
// are the input too.
bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

// An image module's encoder hands the file's bytes here; they are
// written (and any failure kept) before it returns.
struct FileSink {
    explicit FileSink(const std::string& path) : target(&path) {}
    const std::string* target;
    std::string message;
    bool called = false;
    static void receive(void* context, const void* bytes, std::size_t size) {
        auto* sink = static_cast<FileSink*>(context);
        sink->called = true;
        try {
            sink->message = replace_file(*sink->target, bytes, size);
        } catch (const std::exception& e) {  // nothing may unwind through the module's C frames
            sink->message = e.what();
        }
    }
};

// `-o -`: the encoded file to standard output, every write checked (a
// closed pipe or a full disk is an error, not a short image).
std::string write_stdout(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(STDOUT_FILENO, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return std::strerror(n < 0 ? errno : EIO);
        p += n;
        size -= std::size_t(n);
    }
    return {};
}

// A writer's failure (empty: none) as the one-line ImageWriteError.
void throw_if_failed(const std::string& path, std::string message) {
    if (message.empty()) return;
    std::replace(message.begin(), message.end(), '\n', ' ');
    throw ImageWriteError("cannot write " + path + ": " + message);
}

}  // namespace

void check_output_path(const std::string& path, int width, int height, const std::vector<std::string>& inputs) {
    if (path == "-") return;  // standard output, PNG
    const fs::path target(path);
    const std::string ext = target.extension().string();
    const std::string lower = lower_extension(target);
    if (lower != ".png" && lower != ".pfm" && !image_module(lower).can_write(path.c_str()))
        throw ImageWriteError("cannot write " + path + ": " +
                              (ext.empty() ? std::string("no extension to choose the image format by")
                                           : "OpenImageIO cannot write '" + ext + "' files"));
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw ImageWriteError("cannot write " + path + ": it is a folder");
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(folder, ec))
        throw ImageWriteError("cannot write " + path + ": no folder '" + folder.string() + "'");
    for (const std::string& input : inputs)
        if (same_file(path, input))
            throw ImageWriteError("cannot write " + path + ": it is the input file " + input);
    check_size(path, lower_extension(target), width, height);
    // The folder must accept the temporary file write_image() renames over
    // the target (permissions, read-only mounts).
    if (const std::string why = probe_folder(path); !why.empty())
        throw ImageWriteError("cannot write " + path + ": " + why);
}

bool is_8bit_output(const std::string& path) { return path == "-" || !is_float_format(lower_extension(fs::path(path))); }

bool is_png_output(const std::string& path) { return path == "-" || lower_extension(fs::path(path)) == ".png"; }

void write_encoded(const std::vector<unsigned char>& file, const std::string& path) {
    throw_if_failed(path, path == "-" ? write_stdout(file.data(), file.size())
                                      : replace_file(path, file.data(), file.size()));
}

void write_image(const Image& given, const std::string& path, const PngText& text, int band_row,
                 const std::function<void()>& on_encoded) {
    const bool to_stdout = path == "-";
    const std::string ext = to_stdout ? ".png" : lower_extension(fs::path(path));
    // A PGM is grey by its name: a colour image becomes its luminance.
    const bool grey = ext == ".pgm" && given.channels == 3;
    const Image converted = grey ? grey_image(given) : Image{};
    const Image& image = grey ? converted : given;
    const std::size_t size = std::size_t(image.width) * image.height * image.channels;
    const bool as_bytes = !image.srgb8.empty();
    if (image.width < 1 || image.height < 1 || image.channels < 1 ||
        (as_bytes ? image.srgb8.size() != size || image.content != ImageContent::Color
                  : image.pixels.size() != size))
        throw ImageWriteError("cannot write " + path + ": the image is empty or inconsistent");
    const bool as_float = is_float_format(ext);
    if (as_float && as_bytes)
        throw ImageWriteError("cannot write " + path + ": the image was rendered in 8 bits, the format holds floats");
    check_size(path, ext, image.width, image.height);
    const bool srgb = !as_float && image.content == ImageContent::Color;
    BigVector<std::uint8_t> encoded;
    if (!as_float && !as_bytes) encoded = encode_8bit(image);
    const std::uint8_t* bytes = as_bytes ? image.srgb8.data() : encoded.data();
    // Every format is encoded into memory, then written by replace_file().
    std::string message;
    if (ext == ".pfm") {
        if (image.channels != 1 && image.channels != 3)
            throw ImageWriteError("cannot write " + path + ": PFM holds 1 or 3 channels, the image has " +
                                  std::to_string(image.channels));
        const std::vector<unsigned char> file = encode_pfm(image);
        message = replace_file(path, file.data(), file.size());
    } else if (ext == ".png") {
        std::vector<unsigned char> file;
        message = encode_png(file, bytes, image.width, image.height, image.channels, srgb, text, band_row);
        if (message.empty()) {
            if (on_encoded) on_encoded();
            return write_encoded(file, path);
        }
    } else {
        const ImageModule& module = image_module(ext);
        char error[512] = "";
        const void* data = as_float ? static_cast<const void*>(image.pixels.data()) : bytes;
        FileSink sink(path);
        if (!module.encode(path.c_str(), data, as_float, image.width, image.height, image.channels, srgb,
                         FileSink::receive, &sink, error, sizeof error))
            message = error[0] ? error : "write failed";
        else
            message = sink.called ? sink.message : "the encoder produced no file";
    }
    throw_if_failed(path, message);
    if (on_encoded) on_encoded();
}

}  // namespace kerf::render
