// Helpers shared by the grammar tests: parse a string, render the AST as an
// s-expression, or capture the one-line diagnostic of a failing parse.
#pragma once
#include <memory>
#include <string>

#include "grammar/ast_print.hpp"
#include "grammar/parser.hpp"

namespace kerf::test {

inline std::shared_ptr<const SourceFile> source(std::string text, std::string path = "t.sdl") {
    auto f = std::make_shared<SourceFile>();
    f->path = std::move(path);
    f->text = std::move(text);
    return f;
}

inline ast::Program parse(std::string text, std::size_t max_nesting = 256) {
    return parse_program(source(std::move(text)), ParseOptions{max_nesting});
}

// The whole program as s-expressions, one statement per line.
inline std::string sx(std::string text) { return ast::to_sexpr(parse(std::move(text))); }

// One expression, parsed as the value of `x = ...;`.
inline std::string ex(const std::string& expr) {
    auto p = parse("x = " + expr + ";");
    return ast::to_sexpr(*p.stmts.at(0)->value);
}

// "PATH:LINE:COL: error: MESSAGE" of the parse, or "no error".
inline std::string error_of(std::string text, std::size_t max_nesting = 256) {
    try {
        parse(std::move(text), max_nesting);
    } catch (const SourceError& e) {
        return format_diagnostic_head(e.diagnostic());
    }
    return "no error";
}

}  // namespace kerf::test
