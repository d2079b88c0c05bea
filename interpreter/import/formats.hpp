// The mesh file formats of import(), each parsed from the file into meshes
// in the file's own (counter-clockwise) face order. mesh_import.cpp
// validates and reorients the result.
#pragma once
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf::eval::mesh_format {

// An import file (a regular file), open for reading. Its size is known
// before any byte is read, so the readers check what a header declares
// against it first, and read only what they need when they need it.
class MeshFile {
public:
    // Throws MeshFormatError when the file cannot be opened or is longer
    // than kMaxImportBytes.
    explicit MeshFile(const std::string& path);
    ~MeshFile();
    MeshFile(const MeshFile&) = delete;
    MeshFile& operator=(const MeshFile&) = delete;

    std::uint64_t size() const { return size_; }
    // Exactly `n` bytes from `offset` into `out`; throws MeshFormatError on a
    // read error or when the file ends first (it shrank while being read).
    void read_exact(std::uint64_t offset, char* out, std::size_t n) const;
    // Up to `n` bytes from `offset`, fewer at the end of the file.
    std::string read(std::uint64_t offset, std::size_t n) const;
    std::string read_all() const { return read(0, static_cast<std::size_t>(size_)); }

private:
    int fd_ = -1;
    std::uint64_t size_ = 0;
};

graph::PolygonMesh read_stl(const MeshFile& file, std::uint64_t max_faces);
graph::PolygonMesh read_obj(std::string_view bytes, std::uint64_t max_faces);
graph::PolygonMesh read_ply(const MeshFile& file, std::uint64_t max_faces);
graph::PolygonMesh read_off(const MeshFile& file, std::uint64_t max_faces);
// AMF's XML is read by the XML module (xml_imports.cpp), a zipped file's
// first unzipped by the zip module.
ImportedMesh read_amf(const MeshFile& file, const std::string& path, const MeshReading& how);
// lib3mf reads the file itself (by its path, after MeshFile checked its size).
// It and libzip live in the zip module, loaded on the first call of either
// (zip_imports.cpp; a module that cannot be loaded is a MeshFormatError).
ImportedMesh read_3mf(const std::string& path, const MeshReading& how);
// The XML of a compressed AMF file (a zip archive): the entry named like the
// file, or its only entry.
std::string unzip_amf(const std::string& path);

// Line number (1-based) of byte offset `at`, for text-format errors.
std::size_t line_of(std::string_view bytes, std::size_t at);

// Whitespace-separated tokens of a text format, with errors that name the
// line of the last token read.
class Tokens {
public:
    explicit Tokens(std::string_view text, std::size_t start = 0) : s_(text), pos_(start), last_(start) {}
    // The next token, or an empty view at the end of the text.
    std::string_view next();
    // The next token, which must be `word` (for keywords of a fixed layout).
    void expect(std::string_view word);
    // The next token as a number; `what` names it in the error.
    double number(const char* what);
    // Skips to the start of the next line (names after 'solid', comments).
    void skip_line();
    bool at_end();
    [[noreturn]] void fail(const std::string& message) const;
    // A bound passed (--max-list): a MeshLimitError at the last token's line.
    [[noreturn]] void fail_limit(const std::string& message) const;
    // A token as error messages quote it: "'facet'" or "the end of the file".
    static std::string quoted(std::string_view token);

private:
    std::string_view s_;
    std::size_t pos_;
    std::size_t last_;  // start of the last token, for error lines
};

// The lines of a text format with '#' comments cut off and blank lines
// skipped (OBJ, OFF), each read through Tokens so errors name its number.
class Lines {
public:
    explicit Lines(std::string_view text, std::size_t from = 0) : s_(text), pos_(from) {}
    // The next line that is not blank, or none at the end of the text.
    std::optional<Tokens> next();
    // The next line that must be there: at the end, an error naming `what`.
    Tokens need(const char* what);
    std::size_t left() const { return pos_ < s_.size() ? s_.size() - pos_ : 0; }

private:
    std::string_view s_;
    std::size_t pos_;
};

// A number token: decimal or scientific, an optional leading '+'. Returns
// false when the whole token is not a number.
inline bool parse_number(std::string_view tok, double& out) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    if (tok.empty()) return false;
    auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), out);
    return ec == std::errc() && end == tok.data() + tok.size();
}

// Refuses a count of items that could not fit in the bytes left (each item
// needs at least `min_bytes`; `slack` more bytes are allowed for, e.g. the
// missing separator after a text file's last number), before anything is
// allocated for them.
void check_count(std::uint64_t count, std::uint64_t bytes_left, std::size_t min_bytes, const std::string& what,
                 std::uint64_t limit, std::uint64_t slack = 0);

}  // namespace kerf::eval::mesh_format
