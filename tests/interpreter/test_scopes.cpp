// Names and scopes (docs/spec.md §3): immutable bindings, shadowing, strict
// undefined names, use before definition, dynamic `$` variables.
#include <catch2/catch.hpp>

#include "tests/interpreter/eval_helpers.hpp"

using kerf::test::echoes;
using kerf::test::error_of;
using kerf::test::value_of;

TEST_CASE("a second binding in one block is an error naming both lines", "[scope]") {
    CHECK(error_of("x = 1;\ny = 2;\nx = 3;") == "test.sdl:3:1: error: 'x' is already defined at line 1");
    CHECK(error_of("module m() {\n  a = 1;\n  a = 2;\n}\nm();") == "test.sdl:3:3: error: 'a' is already defined at line 2");
    CHECK(error_of("function f() = 1;\nfunction f() = 2;") == "test.sdl:2:1: error: function 'f' is already defined at line 1");
    CHECK(error_of("module m() {}\nmodule m() {}") == "test.sdl:2:1: error: module 'm' is already defined at line 1");
}

TEST_CASE("blocks may shadow outer names", "[scope]") {
    auto lines = echoes("x = 1;\nmodule m() { x = 2; echo(x); }\nm();\necho(x);\nif (true) { x = 3; echo(x); }");
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == "ECHO: 2");
    CHECK(lines[1] == "ECHO: 1");
    CHECK(lines[2] == "ECHO: 3");
}

TEST_CASE("undefined names are errors", "[scope]") {
    CHECK(error_of("echo(foo);") == "test.sdl:1:6: error: undefined name 'foo'");
    CHECK(error_of("x = [1, bar];") == "test.sdl:1:9: error: undefined name 'bar'");
    CHECK(error_of("echo($nosuch);") == "test.sdl:1:6: error: undefined name '$nosuch'");
    CHECK(error_of("module m() { y = 1; }\nm();\necho(y);") == "test.sdl:3:6: error: undefined name 'y'");
}

TEST_CASE("assignments run first, in order (decision documented in evaluator.hpp)", "[scope]") {
    // A statement may use a name assigned below it, as in OpenSCAD.
    CHECK(echoes("echo(x);\nx = 5;") == std::vector<std::string>{"ECHO: 5"});
    // An assignment may not use a later one.
    CHECK(error_of("a = b + 1;\nb = 2;") == "test.sdl:1:5: error: 'b' is used before its definition at line 2");
    // Not even through a function.
    CHECK(error_of("function f() = k;\na = f();\nk = 3;") ==
          "test.sdl:1:16: error: 'k' is used before its definition at line 3");
    // Functions and modules are hoisted.
    CHECK(value_of("f(2)", "function f(x) = g(x) * 2;\nfunction g(x) = x + 1;") == "6");
}

TEST_CASE("$ variables are dynamically scoped", "[scope]") {
    const char* src =
        "module show() echo($x);\n"
        "module outer() { $x = 7; show(); }\n"
        "$x = 1;\n"
        "show();\n"
        "outer();\n"
        "show($x = 3);\n"
        "function f() = $x;\n"
        "echo(let ($x = 9) f());\n";
    CHECK(echoes(src) == std::vector<std::string>{"ECHO: 1", "ECHO: 7", "ECHO: 3", "ECHO: 9"});
    // Tessellation settings are accepted with OpenSCAD's defaults and ignored.
    CHECK(value_of("[$fn, $fa, $fs]") == "[0, 12, 2]");
    CHECK(value_of("$fn", "$fn = 64;") == "64");
}

TEST_CASE("children see the module's $ variables (OpenSCAD dynamic scope)", "[scope]") {
    CHECK(echoes("module m() { $c = 5; children(); }\nm() echo($c);") == std::vector<std::string>{"ECHO: 5"});
}
