// Entry points of the grammar stage: text in, AST out, or one located error.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "grammar/ast.hpp"
#include "grammar/source.hpp"

namespace kerf {

struct ParseOptions {
    std::size_t max_nesting = 256;  // docs/spec.md §8: nesting depth of source
    // OpenSCAD's lexical leniency (docs/openscad.md): names may start with a
    // digit (`608_dia`), list elements and arguments may be empty
    // (`[1,,2]`), `for` in a list may be C-style.
    bool openscad = false;
};

// Thrown when a file cannot be read (CLI exit status 2, not 1).
class IoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads a whole file (regular, pipe or device); throws IoError naming the
// path and the reason, also when it is longer than kMaxSourceBytes.
constexpr std::size_t kMaxSourceBytes = std::size_t(256) << 20;
std::shared_ptr<const SourceFile> read_source_file(const std::string& path);

// Parses a whole script. Throws SourceError at the first syntax error, whose
// message says what was expected ("expected ';'"), located at the offending
// byte. Never crashes on any byte sequence; nesting is limited.
ast::Program parse_program(std::shared_ptr<const SourceFile> file, const ParseOptions& limits = {});

}  // namespace kerf
