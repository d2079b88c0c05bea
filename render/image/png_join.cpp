#include "render/image/png_join.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>
#include <zlib.h>

#include "render/image/png_file.hpp"
#include "render/image/png_read.hpp"

namespace kerf::render {

namespace {

std::uint32_t big_endian(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// The chunks of `file` up to IEND, each CRC checked, into `band`.
std::string read_chunks(const std::vector<unsigned char>& file, PngBand& band) {
    static const unsigned char signature[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};
    if (file.size() < 8 || !std::equal(signature, signature + 8, file.begin())) return "not a PNG file";
    bool header = false;
    for (std::size_t at = 8;;) {
        if (file.size() - at < 8) return "the file ends early";
        const std::uint32_t length = big_endian(file.data() + at);
        const std::string type(reinterpret_cast<const char*>(file.data() + at + 4), 4);
        if (length > 0x7fffffffu) return type + ": chunk too long";
        if (file.size() - at - 8 < std::size_t(length) + 4) return "the file ends early";
        const unsigned char* data = file.data() + at + 8;
        const uLong crc = crc32(crc32(0, file.data() + at + 4, 4), data, uInt(length));
        if (crc != big_endian(data + length)) return type + ": CRC error";
        at += 12 + std::size_t(length);
        if (!header) {
            // IHDR: width, height, depth, colour type, compression, filter, interlace.
            if (type != "IHDR" || length != 13) return "IHDR: missing";
            band.width = int(std::min<std::uint32_t>(big_endian(data), 1u << 20));
            band.height = int(std::min<std::uint32_t>(big_endian(data + 4), 1u << 20));
            band.channels = data[9] == 0 ? 1 : data[9] == 2 ? 3 : data[9] == 6 ? 4 : 0;
            if (data[8] != 8 || band.channels == 0 || data[10] != 0 || data[11] != 0 || data[12] != 0 ||
                band.width < 1 || band.height < 1 || band.width >= 1 << 20 || band.height >= 1 << 20)
                return "not a non-interlaced 8-bit grey, RGB or RGBA PNG";
            header = true;
        } else if (type == "IDAT") {
            band.stream.insert(band.stream.end(), data, data + length);
        } else if (type == "tEXt") {
            const unsigned char* nul = std::find(data, data + length, 0);
            if (nul == data + length) return "tEXt: no keyword";
            band.text.emplace_back(std::string(data, nul), std::string(nul + 1, data + length));
        } else if (type == "sRGB") {
            band.srgb = true;
        } else if (type == "IEND") {
            return {};
        }
    }
}

// The pieces table against the image data: as many pieces as the rows make,
// their sizes adding up to the stream's, the framing zlib_stream() writes
// and the Adler-32 of them all. Sets each piece's data and length.
std::string check_pieces(PngBand& band) {
    int first_row = -1;
    for (const auto& [key, value] : band.text)
        if (key == kPiecesKeyword && !parse_pieces_table(value, first_row, band.pieces))
            return "its table of image data pieces is damaged";
    if (first_row < 0) return {};
    const auto rows = piece_rows(first_row, band.height);
    if (rows.size() != band.pieces.size()) return "its table of image data pieces does not fit its rows";
    const std::size_t stride = std::size_t(band.width) * std::size_t(band.channels);
    std::size_t at = kStreamHead;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        PieceData& p = band.pieces[k];
        if (p.size > band.stream.size() - at) return "its image data is shorter than its table of pieces";
        p.data = band.stream.data() + at;
        p.length = (stride + 1) * std::size_t(rows[k][1] - rows[k][0]);
        at += p.size;
    }
    const std::vector<unsigned char>& s = band.stream;
    if (s.size() != at + kStreamTail || s[0] != 0x78 || s[1] != 0x01 || s[at] != 0x03 || s[at + 1] != 0x00)
        return "its image data is not framed as its table of pieces says";
    if (big_endian(&s[at + 2]) != combined_adler(band.pieces)) return "its image data: incorrect data check";
    band.first_row = first_row;
    return {};
}

}  // namespace

std::string read_png_band(const std::string& path, PngBand& band) {
    std::vector<unsigned char> file;
    if (std::string why = read_file_bytes(path, file); !why.empty()) return why;
    band = PngBand{};
    if (std::string why = read_chunks(file, band); !why.empty()) return why;
    return check_pieces(band);
}

std::string decode_band(const PngBand& band, std::uint8_t* pixels) {
    const auto rows = piece_rows(band.first_row, band.height);
    const std::size_t stride = std::size_t(band.width) * std::size_t(band.channels);
    std::vector<std::string> errors(rows.size());
    tbb::parallel_for(std::size_t(0), rows.size(), [&](std::size_t k) {
        errors[k] = inflate_piece(band.pieces[k], band.width, band.channels, rows[k][1] - rows[k][0],
                                  pixels + stride * std::size_t(rows[k][0]));
    });
    for (const std::string& e : errors)
        if (!e.empty()) return e;
    return {};
}

std::string join_png_bands(std::vector<unsigned char>& file, const std::vector<const PngBand*>& bands,
                           const PngBand** culprit) {
    const PngBand& top = *bands.front();
    const int width = top.width, channels = top.channels;
    const std::size_t stride = std::size_t(width) * std::size_t(channels);
    // Every band's pieces, by the full image's row they start at.
    struct Piece {
        const PngBand* band;
        int from, to;  // full-image rows
        const PieceData* data;
    };
    std::vector<Piece> band_pieces;
    int height = 0;
    for (const PngBand* b : bands) {
        if (b->first_row != height || b->width != width || b->channels != channels || b->srgb != top.srgb)
            return "the bands do not make one image";
        const auto rows = piece_rows(b->first_row, b->height);
        for (std::size_t k = 0; k < rows.size(); ++k)
            band_pieces.push_back({b, b->first_row + rows[k][0], b->first_row + rows[k][1], &b->pieces[k]});
        height += b->height;
    }
    // The full image's pieces: a band's own where one matches, else decoded
    // from the band pieces it is made of (all inside it: both are cut at
    // every multiple of kPieceRows) and deflated again.
    const auto rows = piece_rows(0, height);
    std::vector<PieceData> pieces(rows.size());
    std::vector<std::vector<unsigned char>> again(rows.size());
    std::vector<std::string> errors(rows.size());
    std::vector<const PngBand*> from_band(rows.size(), nullptr);
    std::vector<std::size_t> first(rows.size());  // the first band piece of each
    for (std::size_t k = 0, i = 0; k < rows.size(); ++k) {
        while (band_pieces[i].from < rows[k][0]) ++i;
        first[k] = i;
    }
    tbb::parallel_for(std::size_t(0), rows.size(), [&](std::size_t k) {
        const auto [from, to] = rows[k];
        const Piece& own = band_pieces[first[k]];
        if (own.from == from && own.to == to) {
            pieces[k] = *own.data;
            return;
        }
        std::vector<std::uint8_t> pixels(stride * std::size_t(to - from));
        for (std::size_t i = first[k]; i < band_pieces.size() && band_pieces[i].to <= to; ++i) {
            const Piece& p = band_pieces[i];
            const std::string why = inflate_piece(*p.data, width, channels, p.to - p.from,
                                                  pixels.data() + stride * std::size_t(p.from - from));
            if (!why.empty()) {
                errors[k] = why, from_band[k] = p.band;
                return;
            }
        }
        if (!deflate_piece(pixels.data(), width, channels, to - from, again[k], pieces[k])) errors[k] = "compression failed";
    });
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (!errors[k].empty()) {
            if (culprit) *culprit = from_band[k];
            return errors[k];
        }
    return png_from_stream(file, zlib_stream(pieces), width, height, channels, top.srgb);
}

}  // namespace kerf::render
