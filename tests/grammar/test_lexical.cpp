// Lexical details (docs/spec.md §1): number and string literal values, names versus
// keywords, comments.
#include <catch2/catch.hpp>

#include <cmath>

#include "grammar/literals.hpp"
#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::parse;
namespace ast = kerf::ast;

namespace {
const ast::Expr& value_of(const ast::Program& p) { return *p.stmts.at(0)->value; }
double number(const std::string& text) {
    auto p = parse("x = " + text + ";");
    REQUIRE(value_of(p).kind == ast::ExprKind::Number);
    return value_of(p).number;
}
std::string string_value(const std::string& literal) {
    auto p = parse("x = " + literal + ";");
    REQUIRE(value_of(p).kind == ast::ExprKind::String);
    return value_of(p).text;
}
}  // namespace

TEST_CASE("number literals", "[grammar][lexical]") {
    CHECK(number("12") == 12.0);
    CHECK(number("1.5") == 1.5);
    CHECK(number(".5") == 0.5);
    CHECK(number("1.") == 1.0);
    CHECK(number("1e-3") == 0.001);
    CHECK(number("2.5E+4") == 25000.0);
    CHECK(number("0.1") == 0.1);  // correctly rounded, like strtod
    CHECK(number("007") == 7.0);
    CHECK(number("1e999") == INFINITY);
    CHECK(number("1e-999") == 0.0);
    CHECK(number("0.000001e-320") == 0.0);
    CHECK(number("100000e-5") == 1.0);
    CHECK(kerf::grammar::parse_number("12abc") == std::nullopt);
    CHECK(kerf::grammar::parse_number("1e+") == std::nullopt);
}

TEST_CASE("string literals and escapes", "[grammar][lexical]") {
    CHECK(string_value(R"("")") == "");
    CHECK(string_value(R"("abc")") == "abc");
    CHECK(string_value(R"("a\"b")") == "a\"b");
    CHECK(string_value(R"("a\\b")") == "a\\b");
    CHECK(string_value(R"("a\nb\tc\rd")") == "a\nb\tc\rd");
    CHECK(string_value(R"("\\\\")") == "\\\\");
    CHECK(string_value("\"two\nlines\"") == "two\nlines");
    CHECK(string_value(R"("// not a comment /* */")") == "// not a comment /* */");
    CHECK(string_value("\"caf\xC3\xA9\"") == "caf\xC3\xA9");
}

TEST_CASE("names, special variables and keywords", "[grammar][lexical]") {
    for (const char* kw : {"module", "function", "if", "else", "for", "let", "include", "use", "true", "false",
                           "undef"}) {
        INFO(kw);
        CHECK(kerf::test::error_of(std::string(kw) + "_x = 1;") == "no error");
        CHECK(kerf::test::error_of(std::string("x = ") + kw + "x;") == "no error");
        CHECK(kerf::test::error_of(std::string(kw) + " = 1;") != "no error");
    }
    CHECK(kerf::test::sx("$children = 1; $fn_2 = $t;") == "(= $children 1)\n(= $fn_2 $t)");
    CHECK(kerf::test::error_of("$ = 1;") == "t.sdl:1:1: error: expected statement");
    CHECK(kerf::test::error_of("x = 2y;") == "t.sdl:1:5: error: malformed number '2y'");
}

TEST_CASE("comments", "[grammar][lexical]") {
    CHECK(kerf::test::sx("// a\nx = 1; // b\n// c") == "(= x 1)");
    CHECK(kerf::test::sx("/**/x/***/=/* * / */1/*\n*/;") == "(= x 1)");
    CHECK(kerf::test::sx("x = 1; //") == "(= x 1)");
    CHECK(kerf::test::sx("x = 1 / 2;") == "(= x (/ 1 2))");
    CHECK(kerf::test::sx("x = 1 // 2;\n;") == "(= x 1)");
}
