// docs/spec.md §8 scripts that parse but must not evaluate: infinite and exponential
// recursion, runaway loops and lists, include cycles, NaN and infinity where
// geometry needs a number. Through the real binary, bounded in time and
// memory (bad_input_checks.hpp).
#include "tests/cli/bad_input_checks.hpp"

namespace fs = std::filesystem;

TEST_CASE("infinite recursion ends at the call depth limit (1000)") {
    const std::string limit = "call depth limit 1000 exceeded";
    expect_errors(test_dir("recursion"),
                  {{"f.sdl", "function f(x) = 1 + f(x + 1);\na = f(0);\n", 1, 21, limit},
                   {"m.sdl", "module m() m();\nm();\n", 1, 12, limit},
                   {"fg.sdl", "function f(x) = g(x);\nfunction g(x) = f(x);\na = f(0);\n", 2, 17, limit},
                   {"children.sdl", "module m() m() children();\nm() cube(1);\n", 1, 12, limit}});
}

TEST_CASE("a function calling itself in tail position without end stops at the tail call limit (10^6)") {
    // OpenSCAD 2021 loops on such calls instead of nesting them, and stops a
    // chain at 1,000,000 passes; so does kerf, in about 0.3 s.
    expect_errors(test_dir("tail_recursion"),
                  {{"t.sdl", "function f(x) = x < 0 ? 0 : f(x + 1);\na = f(0);\n", 1, 29,
                    "tail call limit 1000000 exceeded ('f' calls itself without end?)"}});
}

TEST_CASE("recursion deeper than the stack, with the call limit raised, is an error, not a crash") {
    auto dir = test_dir("recursion_stack");
    const auto path = write_file(dir / "deep.sdl", "function f(n) = n <= 0 ? 0 : 1 + f(n - 1);\na = f(999990);\n");
    const Located head = reject(path, dir, "--max-call-depth 1000000");
    // Whichever nested call or operand reaches the stack guard first is
    // reported: inside the function's body, not at a fixed column.
    CHECK(head.line == 1);
    CHECK(head.col >= 17);
    CHECK(head.message == "evaluation nested too deeply (stack exhausted; lower the call depth limit)");
}

TEST_CASE("exponential recursion ends at the evaluation step limit") {
    auto dir = test_dir("exponential");
    // f(n) makes 2^(n+1) - 1 calls: f(10) needs exactly 2047 steps. (The
    // default limit, 10^8 steps, takes ~20 s to reach: the flag keeps the
    // same path fast.)
    const auto path = write_file(dir / "exp.sdl", "function f(n) = n <= 0 ? 1 : f(n - 1) + f(n - 1);\na = f(10);\n");
    CHECK(run_kerf_bounded("check '" + path + "' --max-steps 2047", dir).status == 0);
    expect_error(path, dir, 1, 41, "evaluation step limit 2046 exceeded", "--max-steps 2046");
}

TEST_CASE("a loop over [0:1e12] ends at the iteration limit (10^7)") {
    const std::string limit = "loop iteration limit 10000000 exceeded";
    expect_errors(test_dir("loop"),
                  {{"for.sdl", "for (i = [0:1e12]) cube(1);\n", 1, 6, limit},
                   {"tiny_step.sdl", "for (i = [0:1e-300:1]) cube(1);\n", 1, 6, limit},
                   {"list.sdl", "a = [for (i = [0:1e12]) i];\n", 1, 11, limit},
                   // Nested loops count together: 10^4 x 10^4 iterations.
                   {"nested.sdl", "a = [for (i = [0:1e4]) for (j = [0:1e4]) i * j];\n", 1, 29, limit}});
}

TEST_CASE("ranges with a zero step or a non-finite bound are located errors") {
    expect_errors(test_dir("ranges"),
                  {{"zero.sdl", "for (i = [0:0:1]) cube(1);\n", 1, 13, "range step must not be 0"},  // .scad: OpenSCAD's warning
                   {"nan.sdl", "for (i = [0:0/0]) cube(1);\n", 1, 14, "range bound must be finite, got nan"},
                   {"inf.sdl", "for (i = [-1/0:0]) cube(1);\n", 1, 13, "range bound must be finite, got -inf"}});
}

TEST_CASE("a huge list ends at the list size limit (10^7)") {
    auto dir = test_dir("huge_list");
    // Doubling a list 30 times asks for 2^30 elements.
    expect_error(write_file(dir / "concat.sdl",
                            "function dbl(l, n) = n == 0 ? l : dbl(concat(l, l), n - 1);\na = dbl([1], 30);\n"),
                 dir, 1, 39, "concat: list size limit 10000000 exceeded (16777216 elements)");
    // A list nested 100 times in itself is shared, but comparing it or
    // printing it would visit 2^100 elements.
    const std::string tree = "function d(l, n) = n == 0 ? l : d([l, l], n - 1);\na = d([1], 100);\n";
    expect_error(write_file(dir / "compare.sdl", tree + "b = a == a;\n"), dir, 3, 7,
                 "list size limit 10000000 exceeded");
    expect_error(write_file(dir / "str.sdl", tree + "b = str(a);\n"), dir, 3, 5,
                 "str: string length limit 10000000 exceeded");
}

// The element limits bound each list, not a list of 10^7 fresh 1000-element
// lists: memory is the last limit (kerf caps its data size at 3/4 of the
// physical memory; here ulimit makes it 1 GB), and running out of it is a
// located error at the top-level statement.
TEST_CASE("a comprehension of large list literals is bounded in memory") {
    auto dir = test_dir("list_amplify");
    std::string literal = "i";
    for (int k = 1; k < 1000; ++k) literal += ", i";
    const auto path = write_file(dir / "amp.sdl", "a = [for (i = [0:9e6]) [" + literal + "]];\n");
    const KerfRun r = run_kerf_bounded("check '" + path + "'", dir, 60, 1'000'000);
    CHECK(r.status == 1);
    CHECK(first_line(r.err) == path + ":1:1: error: out of memory evaluating this statement");
}

TEST_CASE("an include cycle is a located error naming the cycle") {
    auto dir = test_dir("include_cycle");
    const auto a = write_file(dir / "a.sdl", "cube(1);\ninclude <b.sdl>\n");
    const auto b = write_file(dir / "b.sdl", "include <a.sdl>\n");
    // Reported at the include that closes the cycle, in b.sdl.
    const KerfRun r = run_kerf_bounded("check '" + a + "'", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err) == b + ":1:1: error: include cycle: " + a + " -> " + b + " -> " + a);
    CHECK(run_kerf_bounded("render '" + a + "' -W 8 -H 8 -o '" + (dir / "x.png").string() + "'", dir).status == 1);
    CHECK_FALSE(fs::exists(dir / "x.png"));

    const auto self = write_file(dir / "self.sdl", "include <self.sdl>\n");
    expect_error(self, dir, 1, 1, "include cycle: " + self + " -> " + self);
}

TEST_CASE("sqrt(-1) as a radius is an error at the statement") {
    expect_errors(test_dir("sqrt"),
                  {{"sphere.sdl", "sphere(sqrt(-1));\n", 1, 1, "sphere: r must be finite, got nan"},
                   {"named.sdl", "r = sqrt(-1);\ncylinder(h = 1, r = r);\n", 2, 1,
                    "cylinder: r must be finite, got nan"}});
}

TEST_CASE("NaN and infinity from 1/0 as a size or transform are errors at the statement") {
    const std::string inf = "cube: size must be finite, got inf";
    expect_errors(test_dir("nonfinite"),
                  {{"cube.sdl", "cube(1/0);\n", 1, 1, inf},
                   {"vec.sdl", "x = 0/0;\ncube([1, x, 1]);\n", 2, 1, "cube: size must be finite, got [1, nan, 1]"},
                   {"overflow.sdl", "cube(1e308 * 10);\n", 1, 1, inf},
                   {"translate.sdl", "cube(1);\ntranslate([1/0, 0, 0]) cube(1);\n", 2, 1,
                    "translate: v must be finite, got [inf, 0, 0]"},
                   {"scale.sdl", "scale([1, 1, 0]) sphere(1);\n", 1, 1, "scale: factor must not be 0"}});
}
