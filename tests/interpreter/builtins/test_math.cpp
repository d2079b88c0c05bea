// Numeric built-ins called through find_builtin. Expected values are
// closed-form (exact trigonometric values, definitions of log/round, ...).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "tests/interpreter/builtins/builtin_call.hpp"

using namespace kerf;
using kerf::test::call_builtin;
using kerf::test::list_v;
using kerf::test::str_v;

namespace {
double num(const std::string& f, std::vector<Value> args) {
    Value v = call_builtin(f, std::move(args));
    REQUIRE(v.is_number());
    return v.as_number();
}
std::string error_of(const std::string& f, std::vector<Value> args) {
    try {
        call_builtin(f, std::move(args));
    } catch (const SourceError& e) {
        CHECK(e.diagnostic().loc.line == 7);  // located at the call
        CHECK(e.diagnostic().loc.col == 3);
        return e.diagnostic().message;
    }
    FAIL("expected a SourceError from " << f);
    return {};
}
}  // namespace

TEST_CASE("every spec builtin is registered, unknown names are not", "[builtins]") {
    for (const char* name : {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "pow", "exp", "ln",
                             "log", "abs", "sign", "min", "max", "floor", "ceil", "round", "len", "concat", "norm",
                             "cross", "str", "is_undef", "is_num", "is_bool", "is_string", "is_list"})
        CHECK(find_builtin(name) != nullptr);
    CHECK(find_builtin("sinh") == nullptr);
    CHECK(find_builtin("") == nullptr);
    CHECK(find_builtin("Sin") == nullptr);  // names are case-sensitive
}

TEST_CASE("sin and cos are exact at multiples of 30 and 45 degrees", "[builtins]") {
    CHECK(num("sin", {Value(0)}) == 0);
    CHECK(num("sin", {Value(30)}) == 0.5);
    CHECK(num("sin", {Value(90)}) == 1);
    CHECK(num("sin", {Value(180)}) == 0);
    // The signs of zero are OpenSCAD 2021.01's (measured through 1/x:
    // tests/scripts/openscad/trig_signs.scad); echo prints -0 as 0.
    CHECK(std::signbit(num("sin", {Value(180)})));
    CHECK(std::signbit(num("sin", {Value(-180)})));
    CHECK_FALSE(std::signbit(num("sin", {Value(0)})));
    CHECK_FALSE(std::signbit(num("sin", {Value(-720)})));
    CHECK_FALSE(std::signbit(num("cos", {Value(90)})));
    CHECK(std::signbit(num("cos", {Value(270)})));
    CHECK(num("sin", {Value(270)}) == -1);
    CHECK(num("sin", {Value(-90)}) == -1);
    CHECK(num("sin", {Value(360 * 1000 + 150)}) == 0.5);
    CHECK(num("sin", {Value(45)}) == std::numbers::sqrt2 / 2);
    CHECK(num("sin", {Value(120)}) == std::numbers::sqrt3 / 2);
    CHECK(num("cos", {Value(0)}) == 1);
    CHECK(num("cos", {Value(60)}) == 0.5);
    CHECK(num("cos", {Value(90)}) == 0);
    CHECK(num("cos", {Value(180)}) == -1);
    CHECK(num("cos", {Value(-270)}) == 0);
    CHECK(num("cos", {Value(240)}) == -0.5);
    // Generic angles agree with the radian functions.
    for (double d : {1.0, 17.3, 44.9, 45.1, 89.99, 123.4, 200.5, 331.0, -77.7, 1e4 + 3}) {
        double r = d * std::numbers::pi / 180;
        CHECK(num("sin", {Value(d)}) == Approx(std::sin(r)).margin(1e-14));
        CHECK(num("cos", {Value(d)}) == Approx(std::cos(r)).margin(1e-14));
        // tan is ill-conditioned near 90°: compare only where it is not.
        if (std::abs(std::tan(r)) < 100) CHECK(num("tan", {Value(d)}) == Approx(std::tan(r)).epsilon(1e-12));
    }
    CHECK(std::isnan(num("sin", {Value(std::numeric_limits<double>::infinity())})));
}

TEST_CASE("tan is exact at 0, 45, 135 and infinite at 90", "[builtins]") {
    CHECK(num("tan", {Value(0)}) == 0);
    CHECK(num("tan", {Value(45)}) == 1);
    CHECK(num("tan", {Value(135)}) == -1);
    CHECK(num("tan", {Value(180)}) == 0);
    CHECK(num("tan", {Value(60)}) == std::numbers::sqrt3);
    CHECK(std::isinf(num("tan", {Value(90)})));
}

TEST_CASE("inverse trigonometry returns degrees", "[builtins]") {
    CHECK(num("asin", {Value(1)}) == 90);
    CHECK(num("asin", {Value(0.5)}) == 30);
    CHECK(num("asin", {Value(-1)}) == -90);
    CHECK(num("acos", {Value(0)}) == 90);
    CHECK(num("acos", {Value(-1)}) == 180);
    CHECK(num("acos", {Value(0.5)}) == 60);
    CHECK(num("atan", {Value(1)}) == 45);
    CHECK(num("atan2", {Value(1), Value(1)}) == 45);
    CHECK(num("atan2", {Value(1), Value(-1)}) == 135);   // atan2(y, x)
    CHECK(num("atan2", {Value(-1), Value(0)}) == -90);
    CHECK(num("acos", {Value(0.3)}) == Approx(std::acos(0.3) * 180 / std::numbers::pi).epsilon(1e-14));
    CHECK(std::isnan(num("asin", {Value(2)})));  // domain error: NaN value, not an error
}

TEST_CASE("powers, roots and logarithms", "[builtins]") {
    CHECK(num("sqrt", {Value(16)}) == 4);
    CHECK(std::isnan(num("sqrt", {Value(-1)})));
    CHECK(num("pow", {Value(2), Value(10)}) == 1024);
    CHECK(num("pow", {Value(4), Value(0.5)}) == 2);
    CHECK(num("exp", {Value(0)}) == 1);
    CHECK(num("exp", {Value(1)}) == std::numbers::e);
    CHECK(num("ln", {Value(std::numbers::e)}) == 1);
    CHECK(num("log", {Value(1000)}) == Approx(3).epsilon(1e-15));  // base 10
    CHECK(num("log", {Value(2), Value(8)}) == Approx(3).epsilon(1e-15));  // log(base, x)
    CHECK(std::isinf(num("ln", {Value(0)})));
}

TEST_CASE("abs, sign, floor, ceil, round", "[builtins]") {
    CHECK(num("abs", {Value(-2.5)}) == 2.5);
    CHECK(num("sign", {Value(-3)}) == -1);
    CHECK(num("sign", {Value(0)}) == 0);
    CHECK(num("sign", {Value(1e-300)}) == 1);
    CHECK(num("floor", {Value(-1.5)}) == -2);
    CHECK(num("ceil", {Value(-1.5)}) == -1);
    CHECK(num("round", {Value(2.5)}) == 3);    // half away from zero
    CHECK(num("round", {Value(-2.5)}) == -3);
    CHECK(num("round", {Value(2.4999)}) == 2);
}

TEST_CASE("min and max take several numbers or one list", "[builtins]") {
    CHECK(num("min", {Value(3), Value(1), Value(2)}) == 1);
    CHECK(num("max", {Value(3), Value(1), Value(2)}) == 3);
    CHECK(num("min", {list_v({4, -9, 2})}) == -9);
    CHECK(num("max", {list_v({4, -9, 2})}) == 4);
    CHECK(num("max", {Value(5)}) == 5);
    CHECK(error_of("min", {}) == "min: expected a list or at least one number, got no arguments");
    CHECK(error_of("max", {list_v({})}) == "max: the list is empty");
    CHECK(error_of("min", {Value(1), str_v("a")}) == "min: argument 2: expected a number, got a string");
    CHECK(error_of("max", {Value::list({Value(1), Value(true)})}) ==
          "max: element 1 of the list: expected a number, got a bool");
}

TEST_CASE("norm and cross", "[builtins]") {
    CHECK(num("norm", {list_v({3, 4})}) == 5);
    CHECK(num("norm", {list_v({1, 2, 2})}) == 3);
    CHECK(num("norm", {list_v({})}) == 0);
    CHECK(num("norm", {list_v({3e200, 4e200})}) == Approx(5e200));  // no overflow
    Value c = call_builtin("cross", {list_v({1, 0, 0}), list_v({0, 1, 0})});
    CHECK(c == list_v({0, 0, 1}));
    c = call_builtin("cross", {list_v({1, 2, 3}), list_v({4, 5, 6})});
    CHECK(c == list_v({-3, 6, -3}));
    CHECK(num("cross", {list_v({2, 0}), list_v({0, 3})}) == 6);  // 2D: a number
    CHECK(error_of("cross", {list_v({1, 2, 3}), list_v({1, 2})}) ==
          "cross: expected two 3-vectors or two 2-vectors, got lengths 3 and 2");
    CHECK(error_of("norm", {str_v("ab")}) == "norm: expected a vector (a list of numbers), got a string");
}

TEST_CASE("wrong argument count or type is a located error", "[builtins]") {
    CHECK(error_of("sqrt", {str_v("4")}) == "sqrt: expected a number, got a string");
    CHECK(error_of("sin", {}) == "sin: expected 1 argument, got 0");
    CHECK(error_of("cos", {Value(1), Value(2)}) == "cos: expected 1 argument, got 2");
    CHECK(error_of("pow", {Value(2)}) == "pow: expected 2 arguments, got 1");
    CHECK(error_of("log", {Value(1), Value(2), Value(3)}) == "log: expected 1 or 2 arguments, got 3");
    CHECK(error_of("atan2", {Value(1), Value()}) == "atan2: argument 2: expected a number, got undef");
    CHECK(error_of("abs", {list_v({1})}) == "abs: expected a number, got a list");
    CHECK(error_of("floor", {Value(true)}) == "floor: expected a number, got a bool");
}
