// The three file formats of import(), each parsed from the file's bytes into
// a mesh in the file's own (counter-clockwise) face order. mesh_import.cpp
// validates and reorients the result.
#pragma once
#include <cstdint>
#include <string_view>

#include "interpreter/scene_graph.hpp"

namespace kerf::eval::mesh_format {

graph::PolygonMesh read_stl(std::string_view bytes, std::uint64_t max_faces);
graph::PolygonMesh read_obj(std::string_view bytes, std::uint64_t max_faces);
graph::PolygonMesh read_ply(std::string_view bytes, std::uint64_t max_faces);

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
    // A token as error messages quote it: "'facet'" or "the end of the file".
    static std::string quoted(std::string_view token);

private:
    std::string_view s_;
    std::size_t pos_;
    std::size_t last_;  // start of the last token, for error lines
};

// A number token: decimal or scientific, an optional leading '+'. Returns
// false when the whole token is not a number.
bool parse_number(std::string_view tok, double& out);

// Refuses a count of items that could not fit in the bytes left (each item
// needs at least `min_bytes`), before anything is allocated for them.
void check_count(std::uint64_t count, std::size_t bytes_left, std::size_t min_bytes, const std::string& what,
                 std::uint64_t limit);

}  // namespace kerf::eval::mesh_format
