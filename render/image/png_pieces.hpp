// The image data of kerf's PNG files, cut so that bands of a render can be
// joined without decoding them (`kerf assemble`, docs/farm.md). The rows are
// cut at every multiple of kPieceRows of their row in the full image (and
// at the image's edges); each piece is filtered and deflated on its own:
// its first row filtered Sub (needs no row above), the others Up, deflated
// by a fresh raw deflate stream that ends with a sync flush (byte aligned,
// no final block). The zlib stream is the pieces in order behind the
// header, then an empty final block and the Adler-32 of all filtered bytes
// (combined from the pieces'). So a piece depends only on its own rows: a
// band that starts mid-image holds the very bytes of every piece of the
// full image that lies wholly inside it.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace kerf::render {

// 16 rows: a 4K render's file grows 0.6 % over one cut every 128 rows (a
// piece's Huffman tables and flush), and a join re-encodes at most one
// piece per band edge.
constexpr int kPieceRows = 16;

// The pieces of an image `height` rows tall whose row 0 is row `first_row`
// of the full image: [from, to) in the image's own rows, top to bottom.
std::vector<std::array<int, 2>> piece_rows(int first_row, int height);

// A deflated piece, or a view of one inside a file.
struct PieceData {
    const unsigned char* data = nullptr;
    std::size_t size = 0;
    std::uint32_t adler = 1;  // of the filtered bytes
    std::size_t length = 0;   // filtered bytes: rows * (1 + stride)
};

// Filters and deflates `count` rows of `width` pixels of `channels` bytes
// into `out` (replaced), described by `piece`; false if zlib failed.
bool deflate_piece(const std::uint8_t* rows, int width, int channels, int count, std::vector<unsigned char>& out,
                   PieceData& piece);

// Inflates `piece` into `count` rows of `width` pixels of `channels` bytes
// and undoes the filters; checks the size, the filter types and the
// Adler-32. Returns an empty string, else what is wrong.
std::string inflate_piece(const PieceData& piece, int width, int channels, int count, std::uint8_t* rows);

// The zlib stream of these pieces, in order.
std::vector<unsigned char> zlib_stream(const std::vector<PieceData>& pieces);

// The bytes around the pieces in a zlib_stream(): the header before them,
// the empty final block and the Adler-32 after them.
constexpr std::size_t kStreamHead = 2, kStreamTail = 2 + 4;

// The Adler-32 of the pieces' filtered bytes, one after another.
std::uint32_t combined_adler(const std::vector<PieceData>& pieces);

// A band's table of its pieces, stored as a PNG text chunk of this keyword:
// "row=R" (the full image's row of the band's first row), then each
// piece's deflated size and Adler-32 as "SIZE:ADLER" (decimal, 8 hex digits).
constexpr const char* kPiecesKeyword = "kerf pieces";
std::string pieces_table(int first_row, const std::vector<PieceData>& pieces);

// The table back: first_row, and each piece's size and adler (data and
// length are left for the caller). False if it is not such a table.
bool parse_pieces_table(const std::string& text, int& first_row, std::vector<PieceData>& pieces);

}  // namespace kerf::render
