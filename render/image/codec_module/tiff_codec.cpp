// TIFF through libtiff: contiguous samples (32-bit IEEE floats, or bytes),
// Deflate ("zip", OpenImageIO's default, which kerf used before), one
// strip per 64 rows, a fourth channel marked as associated (premultiplied)
// alpha. Written through client procedures into memory; errors come back
// per handle (TIFFOpenOptions), not through libtiff's global handler.
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include <tiffio.h>

#include "render/image/codec_module/codecs.hpp"

namespace kerf::codec {

namespace {

struct Memory {
    Bytes* bytes;
    std::size_t pos = 0;
};

tmsize_t mem_read(thandle_t h, void* buf, tmsize_t n) {
    Memory& m = *static_cast<Memory*>(h);
    const std::size_t k = m.pos < m.bytes->size() ? std::min(std::size_t(n), m.bytes->size() - m.pos) : 0;
    std::memcpy(buf, m.bytes->data() + m.pos, k);
    m.pos += k;
    return tmsize_t(k);
}
tmsize_t mem_write(thandle_t h, void* buf, tmsize_t n) {
    Memory& m = *static_cast<Memory*>(h);
    if (m.pos + std::size_t(n) > m.bytes->size()) m.bytes->resize(m.pos + std::size_t(n));
    std::memcpy(m.bytes->data() + m.pos, buf, std::size_t(n));
    m.pos += std::size_t(n);
    return n;
}
toff_t mem_seek(thandle_t h, toff_t off, int whence) {
    Memory& m = *static_cast<Memory*>(h);
    const std::size_t base = whence == SEEK_CUR ? m.pos : whence == SEEK_END ? m.bytes->size() : 0;
    m.pos = base + std::size_t(off);
    return toff_t(m.pos);
}
int mem_close(thandle_t) { return 0; }
toff_t mem_size(thandle_t h) { return toff_t(static_cast<Memory*>(h)->bytes->size()); }
int no_map(thandle_t, void**, toff_t*) { return 0; }
void no_unmap(thandle_t, void*, toff_t) {}

// The first error of a handle, kept for the message.
int keep_error(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
    std::string& why = *static_cast<std::string*>(user);
    if (why.empty()) {
        char text[400];
        std::vsnprintf(text, sizeof text, fmt, ap);
        why = std::string(module ? module : "TIFF") + ": " + text;
    }
    return 1;
}
int ignore_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

struct Options {
    explicit Options(std::string& why) : o(TIFFOpenOptionsAlloc()) {
        TIFFOpenOptionsSetErrorHandlerExtR(o, keep_error, &why);
        TIFFOpenOptionsSetWarningHandlerExtR(o, ignore_warning, nullptr);
    }
    ~Options() { TIFFOpenOptionsFree(o); }
    TIFFOpenOptions* o;
};

}  // namespace

std::string encode_tiff(const void* pixels, bool as_float, int width, int height, int channels, Bytes& out) {
    if (channels < 1 || channels > 4) return "TIFF: kerf writes 1 to 4 channels";
    std::string why;
    Options options(why);
    out.clear();
    Memory m{&out};
    TIFF* tif = TIFFClientOpenExt("memory", "w", &m, mem_read, mem_write, mem_seek, mem_close, mem_size, no_map,
                                  no_unmap, options.o);
    if (!tif) return why.empty() ? "TIFF: cannot start the encoder" : why;
    constexpr int kRows = 64;
    const std::size_t sample = as_float ? sizeof(float) : 1, row = sample * std::size_t(channels) * std::size_t(width);
    bool ok = TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(width)) &&
              TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(height)) &&
              TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, std::uint16_t(channels)) &&
              TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, std::uint16_t(8 * sample)) &&
              TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, as_float ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT) &&
              TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK) &&
              TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG) &&
              TIFFSetField(tif, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT) &&
              TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE) &&
              TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, std::uint32_t(kRows));
    if (ok && (channels == 2 || channels == 4)) {
        const std::uint16_t extra = EXTRASAMPLE_ASSOCALPHA;
        ok = TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, std::uint16_t(1), &extra);
    }
    const auto* bytes = static_cast<const unsigned char*>(pixels);
    for (int y = 0; ok && y < height; y += kRows) {
        const int rows = std::min(kRows, height - y);
        // libtiff may compress in place: hand it a copy of the strip.
        std::vector<unsigned char> strip(bytes + std::size_t(y) * row, bytes + std::size_t(y + rows) * row);
        ok = TIFFWriteEncodedStrip(tif, std::uint32_t(y / kRows), strip.data(), tmsize_t(strip.size())) >= 0;
    }
    ok = ok && TIFFWriteDirectory(tif);
    TIFFClose(tif);  // flushes nothing more: the directory is written
    if (!ok || !why.empty()) return why.empty() ? "TIFF: write failed" : why;
    return {};
}

std::string read_tiff(const std::string& path, Pixels& out) {
    std::string why;
    Options options(why);
    TIFF* tif = TIFFOpenExt(path.c_str(), "r", options.o);
    if (!tif) return why.empty() ? "cannot open the image" : why;
    std::uint32_t w = 0, h = 0;
    std::uint16_t n = 1, bits = 8, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG, photometric = 0;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &n);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PHOTOMETRIC, &photometric);
    if (!sane_size(int(std::min<std::uint32_t>(w, 1u << 30)), int(std::min<std::uint32_t>(h, 1u << 30)))) {
        TIFFClose(tif);
        return "image has no pixels or more than 2^28";
    }
    const std::size_t count = std::size_t(w) * h;
    std::vector<float> all;
    // Grey or RGB samples stored plainly (what kerf and most tools write):
    // read as they are, so 16-bit and float keep their precision.
    const bool plain = !TIFFIsTiled(tif) && planar == PLANARCONFIG_CONTIG &&
                       (photometric == PHOTOMETRIC_RGB || photometric == PHOTOMETRIC_MINISBLACK) &&
                       ((format == SAMPLEFORMAT_UINT && (bits == 8 || bits == 16)) ||
                        (format == SAMPLEFORMAT_IEEEFP && bits == 32));
    bool ok = true;
    if (plain) {
        all.resize(count * n);
        std::vector<unsigned char> line(std::size_t(TIFFScanlineSize(tif)));
        for (std::uint32_t y = 0; ok && y < h; ++y) {
            ok = TIFFReadScanline(tif, line.data(), y, 0) >= 0;
            float* row = all.data() + std::size_t(y) * w * n;
            for (std::size_t i = 0; ok && i < std::size_t(w) * n; ++i) {
                if (bits == 8) row[i] = line[i] * (1.0f / 255.0f);  // as OpenImageIO converts
                else if (bits == 16) row[i] = reinterpret_cast<const std::uint16_t*>(line.data())[i] * (1.0f / 65535.0f);
                else row[i] = reinterpret_cast<const float*>(line.data())[i];
            }
        }
    } else {
        // Anything else (palettes, YCbCr, tiles, planes, odd depths): libtiff's
        // 8-bit RGBA conversion.
        n = 4;
        std::vector<std::uint32_t> rgba(count);
        ok = TIFFReadRGBAImageOriented(tif, w, h, rgba.data(), ORIENTATION_TOPLEFT, 0);
        all.resize(count * 4);
        for (std::size_t i = 0; ok && i < count; ++i) {
            all[i * 4] = TIFFGetR(rgba[i]) / 255.0f;
            all[i * 4 + 1] = TIFFGetG(rgba[i]) / 255.0f;
            all[i * 4 + 2] = TIFFGetB(rgba[i]) / 255.0f;
            all[i * 4 + 3] = TIFFGetA(rgba[i]) / 255.0f;
        }
    }
    TIFFClose(tif);
    if (!ok) return why.empty() ? "cannot read the image" : why;
    out.width = int(w), out.height = int(h);
    out.encoded = !(plain && format == SAMPLEFORMAT_IEEEFP);
    to_rgb(all.data(), n, count, out.rgb);
    return {};
}

}  // namespace kerf::codec
