// Built-ins reached through the parser and evaluator: the evaluator finds
// them by name, passes evaluated arguments, and their errors point at the
// call expression.
#include <catch2/catch.hpp>

#include "tests/interpreter/eval_helpers.hpp"

using namespace kerf::test;

TEST_CASE("builtins through scripts", "[builtins]") {
    CHECK(value_of("[sin(30), cos(180), tan(45), asin(1), atan2(1, -1)]") == "[0.5, -1, 1, 90, 135]");
    CHECK(value_of("[for (a = [0 : 90 : 360]) sin(a)]") == "[0, 1, 0, -1, 0]");
    CHECK(value_of("max([for (i = [1:5]) i * i])") == "25");
    CHECK(value_of("min(3, -1, 2) + max(4, 7)") == "6");
    CHECK(value_of("str(\"n=\", len(concat([1, 2], [3])), \" \", norm(cross([1, 0, 0], [0, 1, 0])))") ==
          "\"n=3 1\"");
    CHECK(value_of("[is_num(0/0), is_list([0:1]), is_undef(u)]", "function g(u) = u;\nu = undef;") ==
          "[false, false, true]");
    // A user function shadows a builtin of the same name.
    CHECK(value_of("sin(5)", "function sin(x) = x * 2;") == "10");
}

TEST_CASE("builtin errors are located at the call", "[builtins]") {
    CHECK(error_of("x = 1 + sqrt(\"a\");") == "test.sdl:1:9: error: sqrt: expected a number, got a string");
    CHECK(error_of("\n  y = pow(2);") == "test.sdl:2:7: error: pow: expected 2 arguments, got 1");
    CHECK(error_of("z = min([]);") == "test.sdl:1:5: error: min: the list is empty");
}
