// Robustness (docs/spec.md §8): deep nesting of every recursive construct ends in a
// located "nesting deeper than N" error (never a stack overflow), huge
// tokens and truncated or random input never crash, the grammar has no
// PEGTL-detectable problems.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/rules_stmt.hpp"
#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::error_of;

namespace {
std::string repeat(const std::string& s, std::size_t n) {
    std::string out;
    out.reserve(s.size() * n);
    for (std::size_t i = 0; i < n; ++i) out += s;
    return out;
}

// The error expected when the nesting limit (256) is exceeded at `col`.
std::string nesting_error(std::size_t col) {
    return "t.sdl:1:" + std::to_string(col) + ": error: nesting deeper than 256";
}
}  // namespace

TEST_CASE("the grammar has no analyzable problems", "[grammar][limits]") {
    CHECK(tao::pegtl::analyze<kerf::grammar::program>(-1) == 0);
}

TEST_CASE("10,000-deep nesting ends in a located error", "[grammar][limits]") {
    const std::size_t n = 10000;
    // Each unit below opens one level; the error is at the unit that opens
    // level 257, counted by hand from the unit's length (k-th unit starts
    // at first column + (k-1) * length).
    CHECK(error_of("x = " + repeat("(", n) + "1;") == nesting_error(5 + 256));
    CHECK(error_of("x = " + repeat("[", n) + "1;") == nesting_error(5 + 256));
    CHECK(error_of(repeat("{", n)) == nesting_error(1 + 256));
    CHECK(error_of("x = " + repeat("-", n) + "x;") == nesting_error(5 + 256));
    CHECK(error_of("x = " + repeat("!", n) + "x;") == nesting_error(5 + 256));
    CHECK(error_of("x = " + repeat("f(", n) + "1;") == nesting_error(5 + 256 * 2 + 1));     // at the '('
    CHECK(error_of("x = " + repeat("a ? b : ", n) + "c;") == nesting_error(5 + 256 * 8 + 2));  // at the '?'
    CHECK(error_of("x = " + repeat("2 ^ ", n) + "2;") == nesting_error(5 + 256 * 4 + 2));      // at the '^'
    // Prefixes: the 256th `let`/`echo` is level 256, its argument '(' is 257.
    CHECK(error_of("x = " + repeat("let (a = 1) ", n) + "1;") == nesting_error(5 + 255 * 12 + 4));
    CHECK(error_of("x = " + repeat("echo(1) ", n) + "1;") == nesting_error(5 + 255 * 8 + 4));
    // Generators inside `[` (level 1): the 255th `for` is level 256.
    CHECK(error_of("x = [" + repeat("for (i = 1) ", n) + "1];") == nesting_error(6 + 254 * 12 + 4));
    CHECK(error_of("x = [" + repeat("if (i) ", n) + "1];") == nesting_error(6 + 255 * 7));
    // Statements: each child statement counts one level, so does each
    // argument list. The k-th chained `translate()` is level k-1, its '(' k.
    CHECK(error_of(repeat("translate() ", n) + "cube();") == nesting_error(1 + 256 * 12 + 9));
    CHECK(error_of(repeat("u() { ", n)) == nesting_error(1 + 256 * 6 + 1));
    // The k-th `if` (k >= 2) is level k-1, its then-child k, `b(` k+1.
    CHECK(error_of(repeat("if (a) b(); else ", n) + "c();") == nesting_error(1 + 255 * 17 + 8));
    // The k-th nested `if` is the child at level k-1: the 258th exceeds.
    CHECK(error_of(repeat("if (a) ", n) + "c();") == nesting_error(1 + 257 * 7));
}

TEST_CASE("operator chains are limited at 16 times the nesting limit (the tree is as deep)", "[grammar][limits]") {
    // k operators build a tree of height k+1; the default limit is 16 * 256 = 4096.
    const std::string chain_error = "error: expression deeper than 4096 (a chain of operators this long must be split)";
    CHECK(error_of("x = 1" + repeat(" + 1", 4095) + ";") == "no error");
    CHECK(error_of("x = 1" + repeat(" + 1", 4096) + ";") == "t.sdl:1:" + std::to_string(7 + 4095 * 4) + ": " + chain_error);  // at the 4096th '+'
    CHECK(error_of("x = a" + repeat("[0]", 4096) + ";") == "t.sdl:1:" + std::to_string(6 + 4095 * 3) + ": " + chain_error);  // at the 4096th '['
    CHECK(error_of("x = a" + repeat(".x", 4096) + ";") == "t.sdl:1:" + std::to_string(6 + 4095 * 2) + ": " + chain_error);
    // With a smaller nesting limit, chains shrink with it.
    CHECK(error_of("x = 1 + 1 + 1;", 1) == "no error");
    CHECK(error_of("x = 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1;", 1) ==
          "t.sdl:1:67: error: expression deeper than 16 (a chain of operators this long must be split)");
}

TEST_CASE("exactly at the limit parses, the limit is configurable", "[grammar][limits]") {
    CHECK(error_of("x = " + repeat("(", 256) + "1" + repeat(")", 256) + ";") == "no error");
    CHECK(error_of(repeat("{", 256) + repeat("}", 256)) == "no error");
    CHECK(error_of(repeat("translate() ", 255) + "cube();") == "no error");
    CHECK(error_of("x = ((1));", 2) == "no error");
    CHECK(error_of("x = (((1)));", 2) == "t.sdl:1:7: error: nesting deeper than 2");
    CHECK(error_of("a() b();", 2) == "no error");
    CHECK(error_of("a() b() c();", 2) == "t.sdl:1:10: error: nesting deeper than 2");  // c's '('
    CHECK(error_of("a() b() { c(); }", 2) == "t.sdl:1:12: error: nesting deeper than 2");  // c's '(' 
}

TEST_CASE("a 1 MB identifier is handled in linear time", "[grammar][limits]") {
    const std::string id = repeat("abcdefgh", 1 << 17);  // 1 MiB
    auto p = kerf::test::parse("x = " + id + ";\n" + id + " = 1;");
    REQUIRE(p.stmts.size() == 2);
    CHECK(p.stmts[0]->value->text.size() == id.size());
    CHECK(p.stmts[1]->name == id);
    CHECK(error_of(id) == "t.sdl:1:" + std::to_string(id.size() + 1) + ": error: expected '('");
    CHECK(error_of(repeat("9", 1 << 20) + ";").find("error: expected statement") != std::string::npos);
    CHECK(error_of("x = " + repeat("9", 1 << 20) + ";") == "no error");  // 1e1048576: +inf
}

TEST_CASE("every prefix of a valid script fails cleanly or parses", "[grammar][limits]") {
    const std::string script = R"(// prefix test
$fn = 32; include <lib.sdl> use "u.sdl"
function f(a, b = 2) = a > 0 ? [for (i = [0 : 1 : a], j = [1, 2]) if (i % 2 == 0) let (k = i * j) k^2 else -i] : undef;
module m(r = 1, h) { %translate([0, 0, h / 2]) cylinder(h = h, r = r, center = true); children(); }
/* block
   comment */ if (f(3)[0].x != "a\"b\\c\n") { m(2) sphere(1); } else if (!true) ; else { # cube([1, 2, 3]); }
for (i = [0:5]) let (a = echo("i", i) assert(i < 9) i * 30) rotate([0, 0, a]) * m(h = 2);
x = [0:2]; y = [1, [2, 3], "s", true, false];
)";
    REQUIRE(error_of(script) == "no error");
    std::size_t errors = 0;
    for (std::size_t n = 0; n < script.size(); ++n) {
        try {
            kerf::test::parse(script.substr(0, n));
        } catch (const kerf::SourceError& e) {
            ++errors;
            const auto& loc = e.diagnostic().loc;
            CHECK(loc.line >= 1);
            CHECK(loc.col >= 1);
            CHECK(!e.diagnostic().message.empty());
        }
    }
    CHECK(errors > script.size() / 2);
}

TEST_CASE("random bytes and token soup never crash", "[grammar][limits]") {
    std::mt19937 rng(12345);
    const char* tokens[] = {"(", ")", "[", "]", "{", "}", ";", ",", "=", "==", "x", "f", "1", ".5", "\"s\"", "for",
                            "if", "else", "let", "module", "function", "include", "<a>", "+", "-", "*", "!", "#",
                            "%", "?", ":", "^", "echo", "assert", "/*", "*/", "//", "\n", " ", ".x", "&&", "||"};
    for (int round = 0; round < 2000; ++round) {
        std::string text;
        const int len = static_cast<int>(rng() % 60);
        for (int i = 0; i < len; ++i) {
            if (round % 4 == 0) text += static_cast<char>(rng() % 256);
            else text += tokens[rng() % std::size(tokens)];
        }
        try {
            kerf::test::parse(text);
        } catch (const kerf::SourceError& e) {
            CHECK(e.diagnostic().loc.line >= 1);
        }
    }
}
