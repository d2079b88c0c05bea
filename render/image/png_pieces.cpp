#include "render/image/png_pieces.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include <emmintrin.h>
#include <zlib.h>

namespace kerf::render {

namespace {

constexpr unsigned char kSub = 1, kUp = 2;  // PNG filter types

// One deflate stream and one filter buffer per thread, reset for each
// piece: a fresh deflateInit2 allocates and clears ~260 KB, a fresh buffer
// is cleared too, and a 2048-row image has 128 pieces. deflateReset leaves
// the stream as deflateInit2 made it, so the bytes are the same. The
// compressed bytes go to a buffer of the thread's too, sized for the worst
// case (deflateBound) once, and only what deflate wrote is copied out: a
// fresh worst-case buffer per piece was cleared in full (~100 KB at 2048
// wide, 128 pieces: 12 MB of memset and page faults for a few KB of output).
struct Deflater {
    z_stream zs{};
    bool ready = false;
    std::vector<unsigned char> filtered, compressed;
    Deflater() = default;
    Deflater(const Deflater&) = delete;
    Deflater& operator=(const Deflater&) = delete;
    ~Deflater() {
        if (ready) deflateEnd(&zs);
    }
    bool reset() {
        if (ready) return deflateReset(&zs) == Z_OK;
        // Level 1 with run-length matching: as fast as level 1 and, on renders
        // (flat backgrounds, smooth shading), files ~40 % smaller.
        ready = deflateInit2(&zs, 1, Z_DEFLATED, -15, 8, Z_RLE) == Z_OK;
        return ready;
    }
};

}  // namespace

std::vector<std::array<int, 2>> piece_rows(int first_row, int height) {
    std::vector<std::array<int, 2>> out;
    for (int from = 0; from < height;) {
        const int row = first_row + from;
        const int to = std::min(height, from + (kPieceRows - row % kPieceRows));
        out.push_back({from, to});
        from = to;
    }
    return out;
}

bool deflate_piece(const std::uint8_t* rows, int width, int channels, int count, std::vector<unsigned char>& out,
                   PieceData& piece) {
    const std::size_t stride = std::size_t(width) * std::size_t(channels);
    static thread_local Deflater deflater;
    const std::size_t length = (stride + 1) * std::size_t(count);
    if (deflater.filtered.size() < length) deflater.filtered.resize(length);
    unsigned char* const filtered = deflater.filtered.data();
    unsigned char* f = filtered;
    for (int y = 0; y < count; ++y) {
        const std::uint8_t* row = rows + stride * std::size_t(y);
        if (y == 0) {
            // Sub: minus the pixel to the left; the first pixel as it is.
            *f++ = kSub;
            std::copy(row, row + std::min<std::size_t>(std::size_t(channels), stride), f);
            for (std::size_t i = std::size_t(channels); i < stride; ++i) f[i] = std::uint8_t(row[i] - row[i - channels]);
        } else {
            *f++ = kUp;
            const std::uint8_t* above = row - stride;
            // 16 bytes at a time (the compiler's -O2 leaves this loop scalar).
            std::size_t i = 0;
            for (; i + 16 <= stride; i += 16) {
                const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + i));
                const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + i));
                _mm_storeu_si128(reinterpret_cast<__m128i*>(f + i), _mm_sub_epi8(a, b));
            }
            for (; i < stride; ++i) f[i] = std::uint8_t(row[i] - above[i]);
        }
        f += stride;
    }
    piece.length = length;
    piece.adler = std::uint32_t(adler32(1, filtered, uInt(length)));
    if (!deflater.reset()) return false;
    z_stream& zs = deflater.zs;
    std::vector<unsigned char>& compressed = deflater.compressed;
    const std::size_t bound = deflateBound(&zs, uLong(length)) + 16;
    if (compressed.size() < bound) compressed.resize(bound);
    zs.next_in = filtered;
    zs.avail_in = uInt(length);
    zs.next_out = compressed.data();
    zs.avail_out = uInt(bound);
    const int rc = deflate(&zs, Z_SYNC_FLUSH);
    const bool ok = rc == Z_OK && zs.avail_in == 0 && zs.avail_out > 0;
    out.assign(compressed.data(), compressed.data() + (bound - zs.avail_out));
    piece.data = out.data();
    piece.size = out.size();
    return ok;
}

std::string inflate_piece(const PieceData& piece, int width, int channels, int count, std::uint8_t* rows) {
    const std::size_t stride = std::size_t(width) * std::size_t(channels);
    if (piece.length != (stride + 1) * std::size_t(count)) return "a piece of the image data has the wrong size";
    // One byte more than the rows need: a piece that holds more is caught.
    std::vector<unsigned char> filtered(piece.length + 1);
    z_stream zs{};
    if (inflateInit2(&zs, -15) != Z_OK) return "out of memory";
    zs.next_in = const_cast<unsigned char*>(piece.data);
    zs.avail_in = uInt(piece.size);
    zs.next_out = filtered.data();
    zs.avail_out = uInt(filtered.size());
    const int rc = inflate(&zs, Z_SYNC_FLUSH);
    const bool whole = (rc == Z_OK || rc == Z_BUF_ERROR) && zs.avail_in == 0 && zs.avail_out == 1;
    inflateEnd(&zs);
    if (!whole) return rc == Z_DATA_ERROR ? "damaged image data" : "a piece of the image data has the wrong size";
    if (adler32(1, filtered.data(), uInt(piece.length)) != piece.adler) return "image data: incorrect data check";
    const unsigned char* f = filtered.data();
    for (int y = 0; y < count; ++y, f += stride + 1) {
        std::uint8_t* row = rows + stride * std::size_t(y);
        if (f[0] != (y == 0 ? kSub : kUp)) return "image data not cut as kerf cuts it (row filters)";
        if (y == 0) {
            std::copy(f + 1, f + 1 + stride, row);
            for (std::size_t i = std::size_t(channels); i < stride; ++i) row[i] = std::uint8_t(row[i] + row[i - channels]);
        } else {
            const std::uint8_t* above = row - stride;
            for (std::size_t i = 0; i < stride; ++i) row[i] = std::uint8_t(f[1 + i] + above[i]);
        }
    }
    return {};
}

std::uint32_t combined_adler(const std::vector<PieceData>& pieces) {
    uLong adler = 1;
    for (const PieceData& p : pieces) adler = adler32_combine(adler, p.adler, z_off_t(p.length));
    return std::uint32_t(adler);
}

std::string pieces_table(int first_row, const std::vector<PieceData>& pieces) {
    std::string table = "row=" + std::to_string(first_row);
    char adler[9];
    for (const PieceData& p : pieces) {
        std::snprintf(adler, sizeof adler, "%08x", unsigned(p.adler));
        // Piece by piece: GCC 12 at -O3 warns a false -Wrestrict on
        // `" " + std::to_string(...)` (its own basic_string inlining).
        table += ' ';
        table += std::to_string(p.size);
        table += ':';
        table += adler;
    }
    return table;
}

bool parse_pieces_table(const std::string& text, int& first_row, std::vector<PieceData>& pieces) {
    pieces.clear();
    const char* at = text.data();
    const char* end = at + text.size();
    auto number = [&](auto& v, int base) {
        const auto [p, ec] = std::from_chars(at, end, v, base);
        const bool ok = ec == std::errc() && p != at;
        at = p;
        return ok;
    };
    if (text.rfind("row=", 0) != 0) return false;
    at += 4;
    if (!number(first_row, 10) || first_row < 0) return false;
    while (at != end) {
        PieceData p;
        std::uint32_t adler = 0;
        if (*at++ != ' ' || !number(p.size, 10) || at == end || *at++ != ':' || end - at < 8) return false;
        const char* digits = at;
        if (!number(adler, 16) || at != digits + 8) return false;
        p.adler = adler;
        pieces.push_back(p);
    }
    return true;
}

std::vector<unsigned char> zlib_stream(const std::vector<PieceData>& pieces) {
    std::size_t size = kStreamHead + kStreamTail;
    for (const PieceData& p : pieces) size += p.size;
    std::vector<unsigned char> stream;
    stream.reserve(size);
    stream.push_back(0x78), stream.push_back(0x01);  // deflate, 32 KiB window, "fastest"; (0x7801 % 31 == 0)
    for (const PieceData& p : pieces) stream.insert(stream.end(), p.data, p.data + p.size);
    // The final block: fixed Huffman codes, nothing but end-of-block.
    stream.push_back(0x03), stream.push_back(0x00);
    const std::uint32_t adler = combined_adler(pieces);
    for (int shift = 24; shift >= 0; shift -= 8) stream.push_back(static_cast<unsigned char>(adler >> shift));
    return stream;
}

}  // namespace kerf::render
