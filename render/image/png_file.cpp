// PNG output: the image data deflated in parallel bands, the chunks around
// it by libpng, all into memory (write.cpp then replaces the file). libpng
// reports errors by longjmp: everything between setjmp and the calls that
// may jump is plain C data (the compressed stream is built before setjmp,
// the output vector is the caller's), so no destructor is ever skipped.
#include "render/image/png_file.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>

#include <algorithm>
#include <new>
#include <vector>

#include <png.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include "render/image/png_jump.hpp"

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

// One band of rows as a raw deflate segment: each row behind its filter
// byte ("up": minus the row above; the first image row has none above).
// Bands are deflated independently, in parallel, and concatenated into one
// zlib stream, as pigz does: every band but the last ends with a sync flush
// (byte aligned, no final-block bit), the last with Z_FINISH.
struct Band {
    std::vector<unsigned char> deflated;
    uLong adler = 1;
    uLong length = 0;  // filtered bytes in, for adler32_combine
    bool ok = false;
};

void deflate_band(const std::uint8_t* pixels, std::size_t stride, int row0, int row1, bool last, Band& band) {
    std::vector<unsigned char> filtered((stride + 1) * std::size_t(row1 - row0));
    unsigned char* out = filtered.data();
    for (int y = row0; y < row1; ++y) {
        const std::uint8_t* row = pixels + stride * std::size_t(y);
        *out++ = y == 0 ? 0 : 2;  // PNG filter type: none / up
        if (y == 0) {
            std::memcpy(out, row, stride);
        } else {
            const std::uint8_t* above = row - stride;
            for (std::size_t i = 0; i < stride; ++i) out[i] = std::uint8_t(row[i] - above[i]);
        }
        out += stride;
    }
    band.length = uLong(filtered.size());
    band.adler = adler32(1, filtered.data(), uInt(filtered.size()));
    z_stream zs{};
    // Level 1 with run-length matching: as fast as level 1 and, on renders
    // (flat backgrounds, smooth shading), files ~40 % smaller.
    if (deflateInit2(&zs, 1, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK) return;
    band.deflated.resize(deflateBound(&zs, uLong(filtered.size())) + 16);
    zs.next_in = filtered.data();
    zs.avail_in = uInt(filtered.size());
    zs.next_out = band.deflated.data();
    zs.avail_out = uInt(band.deflated.size());
    const int rc = deflate(&zs, last ? Z_FINISH : Z_SYNC_FLUSH);
    band.ok = last ? rc == Z_STREAM_END : rc == Z_OK && zs.avail_in == 0;
    band.deflated.resize(band.deflated.size() - zs.avail_out);
    deflateEnd(&zs);
}

// The whole zlib stream (header, bands, adler32 of everything), or empty if
// zlib failed.
std::vector<unsigned char> deflate_image(const std::uint8_t* pixels, std::size_t stride, int height) {
    constexpr int kRowsPerBand = 128;
    const int bands = (height + kRowsPerBand - 1) / kRowsPerBand;
    std::vector<Band> parts(std::size_t(bands), Band{});
    tbb::parallel_for(0, bands, [&](int k) {
        deflate_band(pixels, stride, k * kRowsPerBand, std::min(height, (k + 1) * kRowsPerBand), k + 1 == bands,
                     parts[std::size_t(k)]);
    });
    std::vector<unsigned char> stream{0x78, 0x01};  // deflate, 32 KiB window, "fastest"; (0x7801 % 31 == 0)
    uLong adler = 1;
    for (const Band& b : parts) {
        if (!b.ok) return {};
        stream.insert(stream.end(), b.deflated.begin(), b.deflated.end());
        adler = adler32_combine(adler, b.adler, z_off_t(b.length));
    }
    for (int shift = 24; shift >= 0; shift -= 8) stream.push_back(static_cast<unsigned char>(adler >> shift));
    return stream;
}

// Returns false with sink.message set. libpng writes the signature and the
// header chunks; the image data is deflated above and goes in as IDAT chunks.
bool encode_file(const std::uint8_t* pixels, int width, int height, int channels, bool srgb,
                 std::vector<png_text>& text, ErrorSink& sink) {
    const std::size_t stride = std::size_t(width) * std::size_t(channels);
    const std::vector<unsigned char> idat = deflate_image(pixels, stride, height);
    if (idat.empty()) {
        std::snprintf(sink.message, sizeof sink.message, "compression failed");
        return false;
    }
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

std::string encode_png(std::vector<unsigned char>& file, const std::uint8_t* pixels, int width, int height,
                       int channels, bool srgb, const PngText& text) {
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
    return encode_file(pixels, width, height, channels, srgb, chunks, sink) ? std::string()
                                                                            : std::string(sink.message);
}

}  // namespace kerf::render
