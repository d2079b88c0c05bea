// PNG input through libpng, from the file's bytes in memory. libpng reports
// errors by longjmp: the state it may jump over lives behind a pointer
// (ReadState), allocated before setjmp, so no destructor is skipped and no
// local is left indeterminate.
#include "render/image/png_read.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include <png.h>

#include "render/image/png_jump.hpp"

namespace kerf::render {

namespace {

struct ReadState : PngJump {
    const std::vector<unsigned char>* file = nullptr;
    std::size_t at = 0;
    PngPicture* out = nullptr;
    std::vector<png_bytep> rows;
};

void on_read(png_structp png, png_bytep data, png_size_t size) {
    auto* s = static_cast<ReadState*>(static_cast<PngJump*>(png_get_error_ptr(png)));
    if (s->file->size() - s->at < size) png_error(png, "the file ends early");
    std::memcpy(data, s->file->data() + s->at, size);
    s->at += size;
}

// Everything that may longjmp; false with s.message set.
bool decode(png_structp png, png_infop info, ReadState& s) {
    png_set_read_fn(png, nullptr, on_read);
    png_read_info(png, info);
    png_uint_32 w = 0, h = 0;
    int depth = 0, type = 0, interlace = 0;
    png_get_IHDR(png, info, &w, &h, &depth, &type, &interlace, nullptr, nullptr);
    const int channels = type == PNG_COLOR_TYPE_GRAY ? 1 : type == PNG_COLOR_TYPE_RGB ? 3
                         : type == PNG_COLOR_TYPE_RGB_ALPHA ? 4 : 0;
    if (depth != 8 || channels == 0 || interlace != PNG_INTERLACE_NONE || w > 1u << 20 || h > 1u << 20) {
        std::snprintf(s.message, sizeof s.message, "not a non-interlaced 8-bit grey, RGB or RGBA PNG");
        return false;
    }
    PngPicture& p = *s.out;
    p.width = int(w), p.height = int(h), p.channels = channels;
    p.srgb = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
    p.pixels.resize(std::size_t(w) * h * std::size_t(channels));
    s.rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) s.rows[y] = p.pixels.data() + std::size_t(y) * w * std::size_t(channels);
    png_read_image(png, s.rows.data());
    png_read_end(png, info);  // the chunks after the image, up to IEND, CRCs checked
    png_textp text = nullptr;
    const int n = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < n; ++i)
        p.text.emplace_back(text[i].key, std::string(text[i].text, text[i].text_length));
    return true;
}

}  // namespace

std::string read_file_bytes(const std::string& path, std::vector<unsigned char>& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "cannot open it";
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) return "cannot read it";
    return {};
}

std::string read_png(const std::string& path, PngPicture& picture) {
    std::vector<unsigned char> file;
    if (std::string why = read_file_bytes(path, file); !why.empty()) return why;
    if (file.size() < 8 || png_sig_cmp(file.data(), 0, 8) != 0) return "not a PNG file";
    picture = PngPicture{};
    ReadState state;
    state.file = &file;
    state.out = &picture;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, static_cast<PngJump*>(&state),
                                                png_jump_error, png_no_warning);
    if (!png) return "out of memory";
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(state.jump)) {
        const bool jumped = info != nullptr;  // png_destroy_read_struct() clears info
        png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        return jumped ? std::string(state.message) : "out of memory";
    }
    const bool ok = decode(png, info, state);
    png_destroy_read_struct(&png, &info, nullptr);
    return ok ? std::string() : std::string(state.message);
}

}  // namespace kerf::render
