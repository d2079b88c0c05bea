// Syntax errors: exactly one line "PATH:LINE:COL: error: MESSAGE" naming
// what was expected, located at the offending byte (docs/spec.md §8). The expected
// strings are written by hand from the input.
#include <catch2/catch.hpp>

#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::error_of;

TEST_CASE("missing punctuation says what was expected", "[grammar][errors]") {
    CHECK(error_of("x = 1") == "t.sdl:1:6: error: expected ';'");
    CHECK(error_of("x = 1\ny = 2;") == "t.sdl:1:6: error: expected ';'");  // where the statement ends
    CHECK(error_of("x = 1 // one\n\n/* two */ y = 2;") == "t.sdl:1:6: error: expected ';'");
    CHECK(error_of("cube(1)") == "t.sdl:1:8: error: expected ';'");
    CHECK(error_of("cube(1") == "t.sdl:1:7: error: expected ')'");
    CHECK(error_of("x = (1;") == "t.sdl:1:7: error: expected ')'");
    CHECK(error_of("x = [1, 2;") == "t.sdl:1:10: error: expected ']'");
    CHECK(error_of("x = [1:2;") == "t.sdl:1:9: error: expected ']'");
    CHECK(error_of("x = a[1;") == "t.sdl:1:8: error: expected ']'");
    CHECK(error_of("union() {\n  cube();\n") == "t.sdl:3:1: error: expected '}'");
    CHECK(error_of("x = a ? b;") == "t.sdl:1:10: error: expected ':'");
    CHECK(error_of("if a b();") == "t.sdl:1:4: error: expected '('");
    CHECK(error_of("if (a b();") == "t.sdl:1:7: error: expected ')'");
    CHECK(error_of("x = f(a b);") == "t.sdl:1:9: error: expected ')'");
    CHECK(error_of("for (i in x) a();") == "t.sdl:1:8: error: expected '='");
    CHECK(error_of("function f() 1;") == "t.sdl:1:14: error: expected '='");
    CHECK(error_of("x == 3;") == "t.sdl:1:3: error: expected '('");
}

TEST_CASE("missing expressions and names", "[grammar][errors]") {
    CHECK(error_of("x = ;") == "t.sdl:1:5: error: expected expression");
    CHECK(error_of("x = 1 +;") == "t.sdl:1:8: error: expected expression");
    CHECK(error_of("x = -;") == "t.sdl:1:6: error: expected expression");
    CHECK(error_of("x = 2 ^ ;") == "t.sdl:1:9: error: expected expression");
    CHECK(error_of("x = [1, , 2];") == "t.sdl:1:9: error: expected expression");
    CHECK(error_of("x = echo(1);") == "t.sdl:1:12: error: expected expression");
    CHECK(error_of("x = a.w;") == "t.sdl:1:7: error: expected 'x', 'y' or 'z'");
    CHECK(error_of("for ([1]) a();") == "t.sdl:1:6: error: expected name");
    CHECK(error_of("module if() {}") == "t.sdl:1:8: error: expected module name");
    CHECK(error_of("function () = 1;") == "t.sdl:1:10: error: expected function name");
    CHECK(error_of("module m(1) {}") == "t.sdl:1:10: error: expected parameter name");
    CHECK(error_of("x = [for i];") == "t.sdl:1:10: error: expected '('");
    CHECK(error_of("let = 3;") == "t.sdl:1:5: error: expected '('");  // keywords are not names
    CHECK(error_of("# ;") == "t.sdl:1:3: error: expected module instantiation");
    CHECK(error_of("include <>") == "t.sdl:1:10: error: expected file name");
    CHECK(error_of("include <abc") == "t.sdl:1:13: error: expected '>'");
    CHECK(error_of("use 5") == "t.sdl:1:5: error: expected file name");
}

TEST_CASE("trailing garbage and stray tokens", "[grammar][errors]") {
    CHECK(error_of("x = 1; )") == "t.sdl:1:8: error: expected statement");
    CHECK(error_of("else x();") == "t.sdl:1:1: error: expected statement");
    CHECK(error_of("cube(); }") == "t.sdl:1:9: error: expected statement");
    CHECK(error_of("x = 1;\n\n   @") == "t.sdl:3:4: error: expected statement");
    CHECK(error_of("x = 1 × 2;") == "t.sdl:1:7: error: expected ';'");  // valid UTF-8, not a token
}

TEST_CASE("lexical errors are located at their start", "[grammar][errors]") {
    CHECK(error_of("x = \"abc") == "t.sdl:1:5: error: unterminated string");
    CHECK(error_of("x = \"abc\\") == "t.sdl:1:5: error: unterminated string");
    CHECK(error_of("x = \"a\nb\nc") == "t.sdl:1:5: error: unterminated string");
    CHECK(error_of("x = \"a\\q\";") == "t.sdl:1:7: error: invalid escape sequence in string");
    CHECK(error_of("x = \"\\x41\";") == "no error");  // OpenSCAD's \x, \u, \U in both dialects
    CHECK(error_of("x = \"\\x80\";") == "t.sdl:1:6: error: invalid escape sequence in string");
    CHECK(error_of("x = \"\\u12\";") == "t.sdl:1:6: error: invalid escape sequence in string");
    CHECK(error_of("/* abc") == "t.sdl:1:1: error: unterminated comment");
    // Not nested: the first `*/` ends the comment, the second `*` is a modifier.
    CHECK(error_of("x = 1;\n  /* a /* b */ */") == "t.sdl:2:17: error: expected module instantiation");
    CHECK(error_of("x = 1; /* */ /*\n\n") == "t.sdl:1:14: error: unterminated comment");
    CHECK(error_of("x = 12abc;") == "t.sdl:1:5: error: malformed number '12abc'");
    CHECK(error_of("x = 1e;") == "t.sdl:1:5: error: malformed number '1e'");
    CHECK(error_of("x = 0x1F;") == "t.sdl:1:5: error: malformed number '0x1F'");
}

TEST_CASE("binary garbage and control bytes are invalid characters", "[grammar][errors]") {
    using namespace std::string_literals;
    CHECK(error_of("x = 1;\0"s) == "t.sdl:1:7: error: invalid character");
    CHECK(error_of("x = \"a\x01\";") == "t.sdl:1:7: error: invalid character");
    CHECK(error_of("// \x7f\n") == "t.sdl:1:4: error: invalid character");
    CHECK(error_of("x = 1;\n\xff\xfe") == "t.sdl:2:1: error: invalid character");
    CHECK(error_of("x = \"\xC3\";") == "t.sdl:1:6: error: invalid character");          // truncated sequence
    CHECK(error_of("x = \"\xC0\xAF\";") == "t.sdl:1:6: error: invalid character");      // overlong '/'
    CHECK(error_of("x = \"\xED\xA0\x80\";") == "t.sdl:1:6: error: invalid character");  // surrogate
    CHECK(error_of("x = \"\xF4\x90\x80\x80\";") == "t.sdl:1:6: error: invalid character");  // > U+10FFFF
    CHECK(error_of("\f") == "t.sdl:1:1: error: invalid character");
    // Well-formed UTF-8 in strings and comments is fine, so is a BOM.
    CHECK(error_of("x = \"h\xC3\xA9llo \xE2\x98\xBA \xF0\x9F\x99\x82\"; // \xC3\xA9") == "no error");
    CHECK(error_of("\xEF\xBB\xBFx = 1;") == "no error");
    CHECK(error_of("\xEF\xBB\xBFx = ;") == "t.sdl:1:5: error: expected expression");
}

TEST_CASE("diagnostic carries path, line and caret", "[grammar][errors]") {
    auto file = kerf::test::source("a = 1;\nb = (2;\n", "dir/scene.sdl");
    try {
        kerf::parse_program(file);
        FAIL("no error");
    } catch (const kerf::SourceError& e) {
        CHECK(e.diagnostic().message == "expected ')'");
        CHECK(e.diagnostic().loc.line == 2);
        CHECK(e.diagnostic().loc.col == 7);
        CHECK(e.diagnostic().loc.file == file);
        CHECK(std::string(e.what()) == "dir/scene.sdl:2:7: error: expected ')'");
        CHECK(kerf::format_diagnostic(e.diagnostic()) == "dir/scene.sdl:2:7: error: expected ')'\nb = (2;\n      ^");
    }
}

TEST_CASE("call-site notes follow the diagnostic, each with its line and caret", "[grammar][errors]") {
    auto lib = kerf::test::source("function f(x) = x + \"a\";\n", "lib/f.sdl");
    auto main = kerf::test::source("use <f.sdl>\ny = f(1);\n", "main.sdl");
    kerf::Diagnostic d{kerf::Severity::Error, kerf::SourceLoc{lib, 1, 19}, "cannot apply '+'", 1, {}};
    d.notes.push_back(kerf::Diagnostic{kerf::Severity::Note, kerf::SourceLoc{main, 2, 5}, "in 'f' called from here", 3, {}});
    CHECK(kerf::format_diagnostic(d) ==
          "lib/f.sdl:1:19: error: cannot apply '+'\nfunction f(x) = x + \"a\";\n                  ^\n"
          "main.sdl:2:5: note: in 'f' called from here (3 times)\ny = f(1);\n    ^");
    CHECK(kerf::format_diagnostic_head(d) == "lib/f.sdl:1:19: error: cannot apply '+'");
}
