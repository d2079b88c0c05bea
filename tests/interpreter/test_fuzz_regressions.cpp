// Hostile inputs (docs/spec.md §8: "bad input of any kind ... ends in a located
// error within the limits, never a crash, hang, or unbounded memory use"),
// from adversarial cases written while fuzzing parse+evaluate
// (tests/fuzz/fuzz_eval.cpp). Each must end in a SourceError with a
// location, quickly, under the same small limits the fuzzer uses.
#include <catch2/catch.hpp>

#include <string>

#include "tests/interpreter/eval_helpers.hpp"

using namespace kerf;
using kerf::test::error_of;

namespace {

EvalOptions small_limits() {
    EvalOptions o;
    o.limits.call_depth = 200;
    o.limits.nesting = 64;
    o.limits.loop_iterations = 100'000;
    o.limits.list_elements = 100'000;
    o.limits.primitives = 10'000;
    o.limits.steps = 100'000;
    return o;
}

std::string repeat(const std::string& s, std::size_t n) {
    std::string out;
    out.reserve(s.size() * n);
    for (std::size_t i = 0; i < n; ++i) out += s;
    return out;
}

}  // namespace

TEST_CASE("fuzz regressions: deep source nesting is a parse error", "[fuzz]") {
    const auto o = small_limits();
    CHECK_THAT(error_of("x = " + repeat("(", 100000) + "1" + repeat(")", 100000) + ";", o),
               Catch::Contains("nesting deeper than 64"));
    CHECK_THAT(error_of(repeat("{", 5000) + repeat("}", 5000), o), Catch::Contains("nesting deeper than 64"));
    CHECK_THAT(error_of("x = " + repeat("-", 200000) + "1;", o), Catch::Contains("nesting deeper than 64"));
    CHECK_THAT(error_of("x = 1" + repeat("^1", 100000) + ";", o), Catch::Contains("nesting deeper than 64"));
    CHECK_THAT(error_of("x = " + repeat("[", 300) + repeat("]", 300) + ";", o),
               Catch::Contains("nesting deeper than 64"));
}

TEST_CASE("fuzz regressions: binary garbage is a located syntax error", "[fuzz]") {
    std::string bytes;
    for (int k = 0; k < 20; ++k)
        for (int c = 0; c < 256; ++c) bytes += static_cast<char>(c);
    CHECK_THAT(error_of(bytes, small_limits()), Catch::StartsWith("test.sdl:1:"));
    CHECK_THAT(error_of(std::string("cube(\0);", 8), small_limits()), Catch::StartsWith("test.sdl:1:"));
}

TEST_CASE("fuzz regressions: runaway recursion and growth hit a limit", "[fuzz]") {
    const auto o = small_limits();
    CHECK_THAT(error_of("function f(n) = n == 0 ? 1 : f(n - 1) + f(n - 1); x = f(60);", o),
               Catch::Contains("evaluation step limit 100000 exceeded"));
    CHECK_THAT(error_of("module m(n) { m(n + 1); } m(0);", o), Catch::Contains("call depth limit 200 exceeded"));
    CHECK_THAT(error_of("module m() { children(); m() children(); } m() cube();", o),
               Catch::Contains("call depth limit 200 exceeded"));
    // Doubling strings and lists: bounded before the result is built.
    CHECK_THAT(error_of("function f(n) = n == 0 ? \"ab\" : let (s = f(n - 1)) str(s, s); x = f(40);", o),
               Catch::Contains("str: string length limit 100000 exceeded"));
    CHECK_THAT(error_of("function f(n) = n == 0 ? [1] : let (s = f(n - 1)) concat(s, s); x = f(40);", o),
               Catch::Contains("concat: list size limit 100000 exceeded"));
    // A small structure that shares one list a million times over prints
    // to gigabytes: str() must refuse without walking it all.
    CHECK_THAT(error_of("a = [for (i = [0:99]) i]; b = [for (i = [0:99]) a]; c = [for (i = [0:99]) b];"
                        "x = str(c);",
                        o),
               Catch::Contains("str: string length limit 100000 exceeded"));
    CHECK_THAT(error_of("for (i = [0 : 1e12]) cube();", o), Catch::Contains("loop iteration limit 100000 exceeded"));
    CHECK_THAT(error_of("x = [for (i = [0 : 1e12]) i];", o), Catch::Contains("limit 100000 exceeded"));
    CHECK_THAT(error_of("for (i = [0:200], j = [0:200]) translate([i, j, 0]) cube();", o),
               Catch::Contains("limit"));
}

TEST_CASE("fuzz regressions: extreme numbers stay values or located errors", "[fuzz]") {
    const auto o = small_limits();
    CHECK_THAT(error_of("x = [1, 2][1e300];", o), Catch::Contains("index 1e+300 out of range"));
    CHECK_THAT(error_of("x = [0 : 1e300][1e20];", o), Catch::Contains("out of range"));
    CHECK(error_of("x = [1e308 : -1e308 : -1e308]; y = len(x);", o) == "no error");
    CHECK_THAT(error_of("sphere(0 / 0);", o), Catch::Contains("sphere: r must be finite, got nan"));
    CHECK_THAT(error_of("translate([1 / 0, 0, 0]) cube();", o), Catch::Contains("must be finite"));
    CHECK(error_of("x = sin(1e308) + cos(-1e308) + tan(1e300) + atan2(0, 0) + pow(-8, 1 / 3);", o) == "no error");
}

TEST_CASE("fuzz regressions: include of a device or a missing file", "[fuzz]") {
    // /dev/zero would never end if read; it is not a regular file, so it
    // is not found rather than read.
    CHECK_THAT(error_of("include </dev/zero>", small_limits()), Catch::Contains("cannot find '/dev/zero'"));
    CHECK_THAT(error_of("use </dev/stdin>", small_limits()), Catch::Contains("cannot find"));
}
