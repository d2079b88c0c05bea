// PNG output: the image data deflated in parallel pieces (png_pieces.hpp),
// the chunks around it by libpng, all into memory (write.cpp then replaces
// the file). libpng reports errors by longjmp: everything between setjmp and the calls that
// may jump is plain C data (the compressed stream is built before setjmp,
// the output vector is the caller's), so no destructor is ever skipped.
#include "render/image/png_file.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>

#include <algorithm>
#include <atomic>
#include <new>
#include <vector>

#include <png.h>
#include <tbb/parallel_for.h>

#include "render/image/png_jump.hpp"
#include "render/image/png_pieces.hpp"

namespace kerf::render {

namespace {

struct ErrorSink : PngJump {
    std::vector<unsigned char>* file = nullptr;
};

// libpng's output: appended to the caller's vector. png_error() longjmps,
// so it is called only after the try block has been left.
void on_write(png_structp png, png_bytep data, png_size_t size) {
    auto* sink = static_cast<ErrorSink*>(static_cast<PngJump*>(png_get_error_ptr(png)));
    bool grown = true;
    try {
        sink->file->insert(sink->file->end(), data, data + size);
    } catch (const std::bad_alloc&) {
        grown = false;
    }
    if (!grown) png_error(png, "out of memory");
}

void on_flush(png_structp) {}

// The pieces of the image (png_pieces.hpp), deflated in parallel; false if
// zlib failed.
bool deflate_pieces(const std::uint8_t* pixels, int width, int height, int channels, int first_row,
                    std::vector<std::vector<unsigned char>>& bytes, std::vector<PieceData>& pieces) {
    const auto rows = piece_rows(first_row, height);
    const std::size_t stride = std::size_t(width) * std::size_t(channels);
    bytes.assign(rows.size(), {});
    pieces.assign(rows.size(), PieceData{});
    std::atomic<bool> ok{true};
    tbb::parallel_for(std::size_t(0), rows.size(), [&](std::size_t k) {
        const auto [from, to] = rows[k];
        if (!deflate_piece(pixels + stride * std::size_t(from), width, channels, to - from, bytes[k], pieces[k]))
            ok = false;
    });
    return ok;
}

// Returns false with sink.message set. libpng writes the signature and the
// header chunks; the image data is deflated above and goes in as IDAT chunks.
bool encode_file(const std::vector<unsigned char>& idat, int width, int height, int channels, bool srgb,
                 std::vector<png_text>& text, ErrorSink& sink) {
    sink.file->reserve(idat.size() + 4096);  // the chunks around it are a few hundred bytes
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, static_cast<PngJump*>(&sink),
                                              png_jump_error, png_no_warning);
    if (!png) {
        std::snprintf(sink.message, sizeof sink.message, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(sink.jump)) {
        // png_destroy_write_struct() clears info: test it first, or every
        // libpng error would read "out of memory".
        if (!info) std::snprintf(sink.message, sizeof sink.message, "out of memory");
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return false;
    }
    png_set_write_fn(png, nullptr, on_write, on_flush);
    const int type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                     : channels == 3 ? PNG_COLOR_TYPE_RGB
                                     : PNG_COLOR_TYPE_RGB_ALPHA;
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (!text.empty()) png_set_text(png, info, text.data(), int(text.size()));
    png_write_info(png, info);
    constexpr std::size_t kChunk = std::size_t(1) << 24;  // IDAT chunks of at most 16 MiB
    for (std::size_t at = 0; at < idat.size(); at += kChunk)
        png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), idat.data() + at,
                        std::min(kChunk, idat.size() - at));
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
    png_write_flush(png);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string png_from_stream(std::vector<unsigned char>& file, const std::vector<unsigned char>& idat, int width,
                            int height, int channels, bool srgb, const PngText& text) {
    if (channels != 1 && channels != 3 && channels != 4) return "PNG holds 1, 3 or 4 channels";
    // libpng's view of `text`, built before setjmp (plain C data).
    std::vector<png_text> chunks;
    for (const auto& [key, value] : text) {
        if (key.empty() || key.size() > 79) return "a PNG text keyword holds 1 to 79 characters";
        png_text t{};
        t.compression = PNG_TEXT_COMPRESSION_NONE;
        t.key = const_cast<char*>(key.c_str());
        t.text = const_cast<char*>(value.c_str());
        t.text_length = value.size();
        chunks.push_back(t);
    }
    ErrorSink sink;
    sink.file = &file;
    file.clear();
    return encode_file(idat, width, height, channels, srgb, chunks, sink) ? std::string() : std::string(sink.message);
}

std::string encode_png(std::vector<unsigned char>& file, const std::uint8_t* pixels, int width, int height,
                       int channels, bool srgb, const PngText& text, int band_row) {
    if (channels != 1 && channels != 3 && channels != 4) return "PNG holds 1, 3 or 4 channels";
    std::vector<std::vector<unsigned char>> bytes;
    std::vector<PieceData> pieces;
    if (!deflate_pieces(pixels, width, height, channels, std::max(band_row, 0), bytes, pieces))
        return "compression failed";
    PngText all = text;
    if (band_row >= 0) all.emplace_back(kPiecesKeyword, pieces_table(band_row, pieces));
    return png_from_stream(file, zlib_stream(pieces), width, height, channels, srgb, all);
}

}  // namespace kerf::render
