// surface()'s PNG images through libpng, transformed to what lodepng gives
// OpenSCAD 2021.01 (8-bit RGB: 16-bit samples stripped to their high byte,
// low bit depths and palettes expanded, grey copied to R, G and B, alpha
// dropped, not composited). libpng reports errors by longjmp: what it may
// jump over lives behind a pointer, allocated before setjmp.
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include <png.h>

#include "interpreter/import/formats.hpp"
#include "interpreter/import/height_map.hpp"
#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval {

namespace {

struct Reading {
    std::jmp_buf jump;
    char message[256] = "";
    const std::string* file = nullptr;
    std::size_t at = 0;
    std::uint64_t max_pixels = 0;
    std::vector<unsigned char> pixels;
    std::vector<png_bytep> rows;
    PngLuminance* out = nullptr;
};

Reading& reading(png_structp png) { return *static_cast<Reading*>(png_get_error_ptr(png)); }

void on_error(png_structp png, png_const_charp msg) {
    Reading& r = reading(png);
    std::snprintf(r.message, sizeof r.message, "%s", msg);
    std::longjmp(r.jump, 1);
}

void on_warning(png_structp, png_const_charp) {}

void on_read(png_structp png, png_bytep data, png_size_t size) {
    Reading& r = reading(png);
    if (r.file->size() - r.at < size) png_error(png, "the file ends early (truncated?)");
    std::memcpy(data, r.file->data() + r.at, size);
    r.at += size;
}

// Everything that may longjmp; false with r.message set.
bool decode(png_structp png, png_infop info, Reading& r) {
    png_set_read_fn(png, nullptr, on_read);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (std::uint64_t(w) * h > r.max_pixels) {
        std::snprintf(r.message, sizeof r.message, "%u x %u pixels, more than the limit %llu (--max-list)", w, h,
                      static_cast<unsigned long long>(r.max_pixels));
        return false;
    }
    png_set_strip_16(png);    // the high byte, as lodepng
    png_set_expand(png);      // palette to RGB, grey below 8 bits to 8 (v · 255 / (2^n − 1)), tRNS to alpha
    png_set_gray_to_rgb(png);
    png_set_strip_alpha(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_channels(png, info) != 3 || png_get_bit_depth(png, info) != 8) {
        std::snprintf(r.message, sizeof r.message, "cannot convert the image to 8-bit RGB");
        return false;
    }
    r.pixels.resize(std::size_t(w) * h * 3);
    r.rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) r.rows[y] = r.pixels.data() + std::size_t(y) * w * 3;
    png_read_image(png, r.rows.data());
    png_read_end(png, nullptr);
    PngLuminance& out = *r.out;
    out.width = int(w), out.height = int(h);
    out.rows.resize(std::size_t(w) * h);
    for (std::size_t i = 0; i < out.rows.size(); ++i) {
        const unsigned char* p = r.pixels.data() + 3 * i;
        out.rows[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];  // OpenSCAD's sum, in its order
    }
    return true;
}

}  // namespace

PngLuminance read_png_luminance(const std::string& path, std::uint64_t max_pixels) {
    const mesh_format::MeshFile file(path);
    const std::string bytes = file.read_all();
    if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
        throw MeshFormatError("not a PNG file");
    PngLuminance out;
    Reading r;
    r.file = &bytes;
    r.max_pixels = max_pixels;
    r.out = &out;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, on_error, on_warning);
    if (!png) throw MeshFormatError("out of memory");
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(r.jump)) {
        const bool jumped = info != nullptr;
        png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        throw MeshFormatError(jumped ? std::string("not a readable PNG: ") + r.message : "out of memory");
    }
    const bool ok = decode(png, info, r);
    png_destroy_read_struct(&png, &info, nullptr);
    if (!ok) throw MeshFormatError(r.message);
    return out;
}

}  // namespace kerf::eval
