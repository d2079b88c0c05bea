#include <catch2/catch.hpp>

#include <cmath>

#include "interpreter/value.hpp"

using kerf::Value;

TEST_CASE("numbers print like OpenSCAD (6 significant digits)", "[value]") {
    CHECK(kerf::to_str(Value(1.0)) == "1");
    CHECK(kerf::to_str(Value(0.5)) == "0.5");
    CHECK(kerf::to_str(Value(1.0 / 3.0)) == "0.333333");
    CHECK(kerf::to_str(Value(1e6)) == "1e+6");
    CHECK(kerf::to_str(Value(100000.0)) == "100000");
    CHECK(kerf::to_str(Value(-2.5)) == "-2.5");
    CHECK(kerf::to_str(Value(1e-5)) == "0.00001");
    // OpenSCAD 2021's text for each (openscad -o x.echo): exponent bounds,
    // rounding into the next decade, -0, unpadded exponents.
    CHECK(kerf::to_str(Value(1e-6)) == "1e-6");
    CHECK(kerf::to_str(Value(1.23456789e-5)) == "0.0000123457");
    CHECK(kerf::to_str(Value(999999.5)) == "1e+6");
    CHECK(kerf::to_str(Value(123456789.0)) == "1.23457e+8");
    CHECK(kerf::to_str(Value(1e21)) == "1e+21");
    CHECK(kerf::to_str(Value(-0.0)) == "0");
    CHECK(kerf::to_str(Value(-123456.7)) == "-123457");
    CHECK(kerf::to_str(Value(5e-324)) == "4.94066e-324");
    CHECK(kerf::to_str(Value(99999.95)) == "99999.9");
    CHECK(kerf::to_str(Value(INFINITY)) == "inf");
    CHECK(kerf::to_str(Value(-INFINITY)) == "-inf");
    CHECK(kerf::to_str(Value(NAN)) == "nan");
}

TEST_CASE("str and echo text of compound values", "[value]") {
    Value l = Value::list({Value(1), Value::string("a"), Value(true), Value(), Value::list({})});
    CHECK(kerf::to_str(l) == "[1, \"a\", true, undef, []]");
    CHECK(kerf::to_str(Value::string("hi")) == "hi");
    CHECK(kerf::to_repr(Value::string("hi")) == "\"hi\"");
    CHECK(kerf::to_repr(Value::string("a\"b")) == "\"a\"b\"");  // as OpenSCAD: not escaped
    CHECK(kerf::to_str(Value::range(0, 1, 5)) == "[0 : 1 : 5]");
    CHECK(kerf::to_str(Value(false)) == "false");
}

TEST_CASE("truthiness per spec", "[value]") {
    CHECK_FALSE(Value().truthy());
    CHECK_FALSE(Value(false).truthy());
    CHECK_FALSE(Value(0).truthy());
    CHECK_FALSE(Value::string("").truthy());
    CHECK_FALSE(Value::list({}).truthy());
    CHECK(Value(true).truthy());
    CHECK(Value(-1).truthy());
    CHECK(Value::string("0").truthy());
    CHECK(Value::list({Value()}).truthy());
    CHECK(Value::range(0, 1, -1).truthy());
}

TEST_CASE("equality is structural and type-strict", "[value]") {
    CHECK(Value(1) == Value(1.0));
    CHECK(Value(1) != Value(true));
    CHECK(Value() == Value());
    CHECK(Value::list({Value(1), Value::string("x")}) == Value::list({Value(1), Value::string("x")}));
    CHECK(Value::list({Value(1)}) != Value::list({Value(1), Value(2)}));
    CHECK(Value(NAN) != Value(NAN));
    CHECK(Value::string("a") != Value::string("b"));
}

TEST_CASE("ranges are lazy and count inclusively", "[value]") {
    CHECK(kerf::Range{0, 1, 5}.size() == 6);
    CHECK(kerf::Range{0, 2, 5}.size() == 3);
    CHECK(kerf::Range{5, -1, 0}.size() == 6);
    CHECK(kerf::Range{5, 1, 0}.size() == 0);
    CHECK(kerf::Range{0, -1, 5}.size() == 0);
    CHECK(kerf::Range{0, 0.1, 0.3}.size() == 4);
    CHECK(kerf::Range{0, 1, 1e12}.size() == 1000000000001ull);
    CHECK(kerf::Range{0, 0, 1}.size() == 0);
    CHECK(kerf::Range{0, 1, 0}.size() == 1);
    CHECK(kerf::Range{1, 0.5, 2}.at(2) == 2.0);
}

// Value is a tagged union (value.hpp): its copies share a string, list or
// function, its moves leave undef behind, and an accessor of the wrong
// type throws as std::get did.
TEST_CASE("copies share, moves empty, assignments change the alternative", "[value]") {
    const Value list = Value::list({Value(1), Value::string("a")});
    REQUIRE(list.list_ptr().use_count() == 1);
    {
        Value copy = list;
        CHECK(list.list_ptr().use_count() == 2);
        CHECK(&copy.as_list() == &list.as_list());
        Value moved = std::move(copy);
        CHECK(copy.is_undef());  // NOLINT(bugprone-use-after-move): the moved-from state is specified
        CHECK(list.list_ptr().use_count() == 2);
        moved = Value(2.5);  // a list replaced by a number releases it
        CHECK(list.list_ptr().use_count() == 1);
        CHECK(moved.as_number() == 2.5);
        moved = list;
        CHECK(list.list_ptr().use_count() == 2);
        const Value& alias = moved;
        moved = alias;  // self-assignment keeps it
        CHECK(list.list_ptr().use_count() == 2);
        CHECK(moved == list);
    }
    CHECK(list.list_ptr().use_count() == 1);
    Value s = Value::string("text");
    Value t = s;
    t = Value::range(0, 2, 6);
    CHECK(t.as_range() == kerf::Range{0, 2, 6});
    CHECK(s.as_string() == "text");
    Value b(true);
    Value c = std::move(b);
    CHECK(c.as_bool());
    CHECK_THROWS_AS(list.as_number(), std::bad_variant_access);
    CHECK_THROWS_AS(Value().as_list(), std::bad_variant_access);
    CHECK_THROWS_AS(Value(1).as_string(), std::bad_variant_access);
}
