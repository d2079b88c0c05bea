// Image output, written atomically (temporary file in the destination
// folder, then rename), so readers never see half a file and a failed write
// keeps the previous image. PNG goes through libpng (png_file.cpp); every
// other format through OpenImageIO, loaded only then (oiio_loader.cpp).
#include "render/image/image.hpp"

#include <algorithm>
#include <cstdint>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/image/oiio_loader.hpp"
#include "render/image/png_file.hpp"
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

std::string temp_name(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    // Keeps the extension: OpenImageIO picks the writer by the file name.
    return (target.parent_path() / ("." + target.stem().string() + ".kerf-tmp-" + std::to_string(::getpid()) + "-" +
                                    std::to_string(counter++) + target.extension().string()))
        .string();
}

}  // namespace

void check_output_path(const std::string& path) {
    const fs::path target(path);
    const std::string ext = target.extension().string();
    if (lower_extension(target) != ".png" && !oiio_module().can_write(path.c_str()))
        throw ImageWriteError("cannot write " + path + ": " +
                              (ext.empty() ? std::string("no extension to choose the image format by")
                                           : "OpenImageIO cannot write '" + ext + "' files"));
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw ImageWriteError("cannot write " + path + ": it is a folder");
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(folder, ec))
        throw ImageWriteError("cannot write " + path + ": no folder '" + folder.string() + "'");
    // The folder must accept the temporary file write_image() renames over
    // the target: create and remove one now (permissions, read-only mounts).
    const std::string probe = temp_name(target);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) throw ImageWriteError("cannot write " + path + ": " + std::strerror(errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

bool is_8bit_output(const std::string& path) { return !is_float_format(lower_extension(fs::path(path))); }

void write_image(const Image& image, const std::string& path) {
    const std::size_t size = std::size_t(image.width) * image.height * image.channels;
    const bool as_bytes = !image.srgb8.empty();
    if (image.width < 1 || image.height < 1 || image.channels < 1 ||
        (as_bytes ? image.srgb8.size() != size || image.content != ImageContent::Color
                  : image.pixels.size() != size))
        throw ImageWriteError("cannot write " + path + ": the image is empty or inconsistent");
    const fs::path target(path);
    const std::string ext = lower_extension(target);
    const bool as_float = is_float_format(ext);
    if (as_float && as_bytes)
        throw ImageWriteError("cannot write " + path + ": the image was rendered in 8 bits, the format holds floats");
    const bool srgb = !as_float && image.content == ImageContent::Color;
    const std::string tmp = temp_name(target);
    BigVector<std::uint8_t> encoded;
    if (!as_float && !as_bytes) encoded = encode_8bit(image);
    const std::uint8_t* bytes = as_bytes ? image.srgb8.data() : encoded.data();
    std::string message;
    if (ext == ".png") {
        message = write_png(tmp, bytes, image.width, image.height, image.channels, srgb);
    } else {
        const OiioModule& oiio = oiio_module();
        char error[512] = "";
        const void* data = as_float ? static_cast<const void*>(image.pixels.data()) : bytes;
        if (!oiio.write(tmp.c_str(), data, as_float, image.width, image.height, image.channels, srgb, error,
                        sizeof error))
            message = error[0] ? error : "write failed";
    }
    std::error_code ec;
    if (!message.empty()) {
        fs::remove(tmp, ec);
        std::replace(message.begin(), message.end(), '\n', ' ');
        throw ImageWriteError("cannot write " + path + ": " + message);
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw ImageWriteError("cannot write " + path + ": " + ec.message());
    }
}

}  // namespace kerf::render
