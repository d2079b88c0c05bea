// Expressions of docs/spec.md §2: operators, vectors and matrices, indexing,
// ranges, comprehensions, let/echo/assert prefixes.
#include <catch2/catch.hpp>

#include "tests/interpreter/eval_helpers.hpp"

using kerf::test::error_of;
using kerf::test::echoes;
using kerf::test::value_of;

TEST_CASE("arithmetic and precedence", "[expr]") {
    CHECK(value_of("1 + 2 * 3") == "7");
    CHECK(value_of("(1 + 2) * 3") == "9");
    CHECK(value_of("2 ^ 3 ^ 2") == "512");  // right-associative
    CHECK(value_of("-2 ^ 2") == "-4");       // ^ binds tighter than unary minus
    CHECK(value_of("7 % 3") == "1");
    CHECK(value_of("-7 % 3") == "-1");      // fmod, as OpenSCAD
    CHECK(value_of("1 / 3") == "0.333333");
    CHECK(value_of("1 / 0") == "inf");
    CHECK(value_of("10 - 4 - 3") == "3");
    CHECK(value_of("+5") == "5");
    CHECK(value_of("PI") == "3.14159");
    // Numbers take the evaluator's short way (number_op, unary minus):
    // the sign of zero survives it.
    CHECK(value_of("1 / -0") == "-inf");
    CHECK(value_of("1 / -(0 * 1)") == "-inf");
    CHECK(value_of("1 / (0 * -1)") == "-inf");
    CHECK(value_of("1 / +0") == "inf");
}

TEST_CASE("comparison and logic", "[expr]") {
    CHECK(value_of("1 < 2") == "true");
    CHECK(value_of("2 <= 2") == "true");
    CHECK(value_of("3 > 4") == "false");
    CHECK(value_of("\"abc\" < \"abd\"") == "true");
    CHECK(value_of("[1, 2] == [1, 2]") == "true");
    CHECK(value_of("[1, 2] != [1, 2, 3]") == "true");
    CHECK(value_of("1 == true") == "false");
    CHECK(value_of("undef == undef") == "true");
    CHECK(value_of("!0") == "true");
    CHECK(value_of("!\"\"") == "true");
    CHECK(value_of("![]") == "true");
    CHECK(value_of("!undef") == "true");
    CHECK(value_of("![0]") == "false");
    CHECK(value_of("1 && \"x\"") == "true");
    CHECK(value_of("0 || []") == "false");
    // Short circuit: the right side would be an error.
    CHECK(value_of("false && nope") == "false");
    CHECK(value_of("true || nope") == "true");
    CHECK(value_of("1 < 2 ? \"a\" : \"b\"") == "\"a\"");
    CHECK(value_of("0 ? 1 : 2") == "2");
}

TEST_CASE("vector and matrix arithmetic", "[expr]") {
    CHECK(value_of("[1, 2, 3] + [10, 20, 30]") == "[11, 22, 33]");
    CHECK(value_of("[1, 2] - [1, 1]") == "[0, 1]");
    CHECK(value_of("[1, 2] * 3") == "[3, 6]");
    CHECK(value_of("2 * [1, [2, 3]]") == "[2, [4, 6]]");
    CHECK(value_of("[2, 4] / 2") == "[1, 2]");
    CHECK(value_of("-[1, -2]") == "[-1, 2]");
    CHECK(value_of("[1, 2, 3] * [4, 5, 6]") == "32");
    CHECK(value_of("[[1, 2], [3, 4]] * [1, 1]") == "[3, 7]");
    CHECK(value_of("[1, 1] * [[1, 2], [3, 4]]") == "[4, 6]");
    CHECK(value_of("[[1, 2], [3, 4]] * [[0, 1], [1, 0]]") == "[[2, 1], [4, 3]]");
    CHECK(value_of("[[1, 2, 3]] * [[1], [2], [3]]") == "[[14]]");
}

TEST_CASE("operator type errors are located", "[expr]") {
    CHECK(error_of("x = 1 + \"a\";") == "test.sdl:1:7: error: cannot apply '+' to number and string");
    CHECK(error_of("x = [1, 2] + [1, 2, 3];") == "test.sdl:1:12: error: '+' needs lists of equal length (got 2 and 3)");
    CHECK(error_of("x = undef * 2;") == "test.sdl:1:11: error: cannot apply '*' to undef and number");
    CHECK(error_of("x = -\"a\";") == "test.sdl:1:5: error: cannot apply unary '-' to string");
    CHECK(error_of("x = [1, 2] * [1, 2, 3];") == "test.sdl:1:12: error: '*' needs lists of equal length (got 2 and 3)");
    CHECK(error_of("x = 1 < \"a\";") == "test.sdl:1:7: error: cannot apply '<' to number and string");
    CHECK(error_of("x = 2 / [1];") == "test.sdl:1:7: error: cannot apply '/' to number and list");
}

TEST_CASE("indexing and members", "[expr]") {
    CHECK(value_of("[10, 20, 30][1]") == "20");
    CHECK(value_of("v[2]", "v = [[1, 2], 3, [4, [5]]];") == "[4, [5]]");
    CHECK(value_of("v[2][1][0]", "v = [[1, 2], 3, [4, [5]]];") == "5");
    CHECK(value_of("\"héllo\"[1]") == "\"é\"");
    CHECK(value_of("[0:2:10][3]") == "6");
    CHECK(value_of("[4, 5, 6].x + [4, 5, 6].y + [4, 5, 6].z") == "15");
    // Located at the `[` or `.` of the access.
    CHECK(error_of("x = [1, 2][2];") == "test.sdl:1:11: error: index 2 out of range (length 2)");
    CHECK(error_of("x = [1, 2][-1];") == "test.sdl:1:11: error: index -1 out of range (length 2)");
    CHECK(error_of("x = [1, 2][0.5];") == "test.sdl:1:11: error: index 0.5 is not an integer");
    CHECK(error_of("x = [1, 2][\"a\"];") == "test.sdl:1:11: error: index must be a number, got string");
    CHECK(error_of("x = 5[0];") == "test.sdl:1:6: error: cannot index a number");
    CHECK(error_of("x = [1, 2].z;") == "test.sdl:1:11: error: index 2 out of range (length 2)");
    CHECK(error_of("x = 3;\ny = x.x;") == "test.sdl:2:6: error: '.x' needs a list, got number");
}

TEST_CASE("ranges are end-inclusive and lazy", "[expr]") {
    CHECK(value_of("[for (i = [0:3]) i]") == "[0, 1, 2, 3]");
    CHECK(value_of("[for (i = [0:2:7]) i]") == "[0, 2, 4, 6]");
    CHECK(value_of("[for (i = [3:-1:1]) i]") == "[3, 2, 1]");
    CHECK(value_of("[for (i = [3:1]) i]") == "[]");  // kerf: no implicit swap
    CHECK(value_of("[for (i = [0:-1:3]) i]") == "[]");
    CHECK(value_of("[for (i = [0:0.25:1]) i]") == "[0, 0.25, 0.5, 0.75, 1]");
    CHECK(value_of("[0:1e12]") == "[0 : 1 : 1e+12]");  // never materialised
    CHECK(error_of("x = [0:0:5];") == "test.sdl:1:8: error: range step must not be 0");
    CHECK(error_of("x = [0:\"a\"];") == "test.sdl:1:8: error: range bound must be a number, got string");
    CHECK(error_of("x = [0:1/0];") == "test.sdl:1:9: error: range bound must be finite, got inf");
}

TEST_CASE("list comprehensions", "[expr]") {
    CHECK(value_of("[for (i = [0:4]) i * i]") == "[0, 1, 4, 9, 16]");
    CHECK(value_of("[for (i = [1:6]) if (i % 2 == 0) i]") == "[2, 4, 6]");
    CHECK(value_of("[for (i = [1:4]) if (i < 3) i else -i]") == "[1, 2, -3, -4]");
    CHECK(value_of("[for (i = [1:3]) let (j = i * 10) j + i]") == "[11, 22, 33]");
    CHECK(value_of("[for (i = [0:1], j = [5:6]) [i, j]]") == "[[0, 5], [0, 6], [1, 5], [1, 6]]");
    CHECK(value_of("[for (i = [1:3], j = [1:i]) j]") == "[1, 1, 2, 1, 2, 3]");
    CHECK(value_of("[for (x = [\"a\", [1], 2]) x]") == "[\"a\", [1], 2]");
    CHECK(value_of("[0, for (i = [1:2]) i, 9]") == "[0, 1, 2, 9]");
    CHECK(value_of("[for (c = \"ab\", d = \"xy\") str(c, d)]") == "[\"ax\", \"ay\", \"bx\", \"by\"]");
    CHECK(value_of("len([for (c = \"h€llo\") c])") == "5");
    CHECK(value_of("[for (i = [0:2]) for (j = [0:i]) j]") == "[0, 0, 1, 0, 1, 2]");
    CHECK(error_of("x = [for (i = 5) i];") == "test.sdl:1:11: error: for: expected a range, a list or a string, got number");
    CHECK(error_of("x = [for (i = [0:1], i = [0:1]) i];") ==
          "test.sdl:1:22: error: 'i' is already defined at line 1");
}

TEST_CASE("let, echo and assert in expressions", "[expr]") {
    CHECK(value_of("let (a = 2, b = a * 3) a + b") == "8");
    CHECK(value_of("let (a = 1) let (a = a + 1) a") == "2");  // shadowing in a nested let
    auto lines = echoes("x = echo(\"hi\", n = 2) 5;\necho(x);");
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "ECHO: \"hi\", n = 2");
    CHECK(lines[1] == "ECHO: 5");
    CHECK(value_of("assert(true, \"no\") 7") == "7");
    CHECK(error_of("x = 1;\ny = assert(x > 1, \"x too small\") x;") ==
          "test.sdl:2:5: error: assertion failed: x too small");
    CHECK(error_of("y = assert(false) 1;") == "test.sdl:1:5: error: assertion failed");
    CHECK(error_of("y = let (a = 1, a = 2) a;") == "test.sdl:1:17: error: 'a' is already defined at line 1");
}

TEST_CASE("echo formats values like OpenSCAD", "[expr]") {
    CHECK(value_of("[1, \"s\", true, undef, [0.5, 1e6]]") == "[1, \"s\", true, undef, [0.5, 1e+6]]");
    CHECK(value_of("\"a\\\"b\"") == "\"a\"b\"");  // OpenSCAD does not escape the quote
    auto lines = echoes("echo(1, \"two\", x = [3]);\necho();");
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "ECHO: 1, \"two\", x = [3]");
    CHECK(lines[1] == "ECHO: ");
}

TEST_CASE("builtin functions take names that match their parameters, in order", "[expr]") {
    CHECK(value_of("max(1, 5, 2)") == "5");
    CHECK(value_of("pow(base = 2, exponent = 3)") == "8");
    CHECK(value_of("pow(2, exponent = 3)") == "8");
    CHECK(value_of("log(x = 100)") == "2");
    CHECK(value_of("log(base = 2, x = 8)") == "3");
    CHECK(value_of("lookup(key = 1, table = [[0, 0], [2, 4]])") == "2");
    CHECK(value_of("len([1, 2, 3])") == "3");
    CHECK(error_of("x = sin(a = 1);") ==
          "test.sdl:1:9: error: 'sin': argument 1 is 'degrees', not 'a' (built-in arguments are taken in order)");
    CHECK(error_of("x = pow(exponent = 2, base = 3);") ==
          "test.sdl:1:9: error: 'pow': argument 1 is 'base', not 'exponent' (built-in arguments are taken in order)");
    CHECK(error_of("x = min(a = 1);") ==
          "test.sdl:1:9: error: 'min' takes no argument named 'a' (built-in arguments are taken in order)");
    CHECK(error_of("x = atan2(y = 1, x = 0, z = 2);") ==
          "test.sdl:1:25: error: 'atan2' takes no argument named 'z' (built-in arguments are taken in order)");
    CHECK(error_of("x = nosuch(1);") == "test.sdl:1:5: error: undefined function 'nosuch'");
}
