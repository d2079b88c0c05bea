// len, concat, str and the type tests called through find_builtin.
#include <catch2/catch.hpp>

#include <limits>

#include "tests/interpreter/builtins/builtin_call.hpp"

using namespace kerf;
using kerf::test::call_builtin;
using kerf::test::list_v;
using kerf::test::str_v;

TEST_CASE("len of lists, strings and ranges", "[builtins]") {
    CHECK(call_builtin("len", {list_v({1, 2, 3})}) == Value(3));
    CHECK(call_builtin("len", {list_v({})}) == Value(0));
    CHECK(call_builtin("len", {str_v("hello")}) == Value(5));
    CHECK(call_builtin("len", {str_v("h\xC3\xA9llo")}) == Value(5));  // characters, not bytes
    CHECK(call_builtin("len", {Value::range(0, 2, 10)}) == Value(6));
    CHECK_THROWS_WITH(call_builtin("len", {Value(3)}), Catch::Contains("len: expected a list or a string, got a number"));
}

TEST_CASE("concat appends lists' elements and other values as elements", "[builtins]") {
    Value r = call_builtin("concat", {list_v({1, 2}), Value(3), Value::list({list_v({4})}), str_v("s")});
    REQUIRE(r.is_list());
    const ValueList& l = r.as_list();
    REQUIRE(l.size() == 5);
    CHECK(l[0] == Value(1));
    CHECK(l[2] == Value(3));
    CHECK(l[3] == list_v({4}));  // one level only
    CHECK(l[4] == str_v("s"));
    CHECK(call_builtin("concat", {}) == Value::list({}));
    CHECK(call_builtin("concat", {list_v({})}) == Value::list({}));
    // The result is bounded by the list-size limit.
    CHECK(call_builtin("concat", {list_v({1, 2}), list_v({3})}, 3).as_list().size() == 3);
    CHECK_THROWS_WITH(call_builtin("concat", {list_v({1, 2}), list_v({3, 4})}, 3),
                      Catch::Contains("list size limit 3 exceeded"));
}

TEST_CASE("str concatenates OpenSCAD text forms", "[builtins]") {
    CHECK(call_builtin("str", {}) == str_v(""));
    CHECK(call_builtin("str", {str_v("a"), Value(1), Value(2.5), Value(true), Value()}) == str_v("a12.5trueundef"));
    CHECK(call_builtin("str", {Value::list({Value(1), str_v("x")})}) == str_v("[1, \"x\"]"));
    CHECK(call_builtin("str", {Value(1.0 / 3)}) == str_v("0.333333"));
    CHECK(call_builtin("str", {Value(1e6)}) == str_v("1e+6"));
    CHECK(call_builtin("str", {Value::range(0, 1, 5)}) == str_v("[0 : 1 : 5]"));
    // Bounded before building: exactly at the limit passes, one more fails.
    CHECK(call_builtin("str", {str_v("abc"), str_v("de")}, 5) == str_v("abcde"));
    CHECK_THROWS_WITH(call_builtin("str", {str_v("abc"), str_v("def")}, 5),
                      Catch::Contains("str: string length limit 5 exceeded"));
    // A vast shared structure is rejected without being walked in full:
    // 1000 references to one 1000-element list would print ~6 MB.
    Value inner = list_v({});
    {
        ValueList items(1000, Value(7));
        inner = Value::list(std::move(items));
    }
    ValueList outer(1000, inner);
    CHECK_THROWS_WITH(call_builtin("str", {Value::list(std::move(outer))}, 10000),
                      Catch::Contains("string length limit"));
}

TEST_CASE("type tests", "[builtins]") {
    const Value nan(std::numeric_limits<double>::quiet_NaN());
    CHECK(call_builtin("is_undef", {Value()}) == Value(true));
    CHECK(call_builtin("is_undef", {Value(0)}) == Value(false));
    CHECK(call_builtin("is_num", {Value(0)}) == Value(true));
    CHECK(call_builtin("is_num", {nan}) == Value(false));  // OpenSCAD: NaN is not a number
    CHECK(call_builtin("is_num", {Value(true)}) == Value(false));
    CHECK(call_builtin("is_bool", {Value(false)}) == Value(true));
    CHECK(call_builtin("is_bool", {Value(0)}) == Value(false));
    CHECK(call_builtin("is_string", {str_v("")}) == Value(true));
    CHECK(call_builtin("is_string", {list_v({})}) == Value(false));
    CHECK(call_builtin("is_list", {list_v({})}) == Value(true));
    CHECK(call_builtin("is_list", {Value::range(0, 1, 3)}) == Value(false));
    CHECK_THROWS_WITH(call_builtin("is_num", {}), Catch::Contains("is_num: expected 1 argument, got 0"));
}
