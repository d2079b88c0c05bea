// Functions and modules (docs/spec.md §3): arguments, defaults, recursion,
// children(), $children; statements if/for/let/echo/assert; modifiers.
#include <catch2/catch.hpp>

#include "tests/interpreter/eval_helpers.hpp"

using kerf::test::echoes;
using kerf::test::error_of;
using kerf::test::shape_of;
using kerf::test::value_of;

TEST_CASE("function arguments: positional, named, defaults", "[modules]") {
    const char* defs = "function f(a, b = 2, c = a + 1) = [a, b, c];";
    CHECK(value_of("f(1)", defs) == "[1, 2, 2]");
    CHECK(value_of("f(1, 5)", defs) == "[1, 5, 2]");
    CHECK(value_of("f(c = 0, a = 4)", defs) == "[4, 2, 0]");
    CHECK(value_of("f(10, c = 3)", defs) == "[10, 2, 3]");
    CHECK(value_of("g(1)", "function g(a, b) = [a, b];") == "[1, undef]");  // missing without default: undef
    CHECK(error_of(std::string(defs) + "\nx = f();") == "test.sdl:1:28: error: cannot apply '+' to undef and number");
    CHECK(error_of(std::string(defs) + "\nx = f(1, 2, 3, 4);") == "test.sdl:2:16: error: too many arguments for 'f' (takes 3)");
    CHECK(error_of(std::string(defs) + "\nx = f(q = 1);") == "test.sdl:2:7: error: unknown argument 'q' for 'f'");
    CHECK(error_of(std::string(defs) + "\nx = f(1, a = 2);") == "test.sdl:2:10: error: argument 'a' given twice to 'f'");
}

TEST_CASE("functions are lexically scoped", "[modules]") {
    CHECK(value_of("g()", "k = 1;\nfunction g() = k;\nmodule m() { k = 2; }") == "1");
    CHECK(echoes("k = 1;\nfunction g() = k;\nmodule m() { k = 2; echo(g()); }\nm();") ==
          std::vector<std::string>{"ECHO: 1"});
    CHECK(echoes("module m() { function h(x) = x * 3; echo(h(2)); }\nm();") == std::vector<std::string>{"ECHO: 6"});
    CHECK(error_of("module m() { function h(x) = x; }\nx = h(1);") == "test.sdl:2:5: error: undefined function 'h'");
}

TEST_CASE("recursion", "[modules]") {
    CHECK(value_of("fact(10)", "function fact(n) = n <= 1 ? 1 : n * fact(n - 1);") == "3.6288e+6");
    CHECK(value_of("fib(15)", "function fib(n) = n < 2 ? n : fib(n - 1) + fib(n - 2);") == "610");
    CHECK(shape_of("module tower(n) { cube(1); if (n > 1) translate([0, 0, 1]) tower(n - 1); }\ntower(3);") ==
          "U(U(box,T(U(box,T(box)))))");
}

TEST_CASE("modules: arguments and unknown modules", "[modules]") {
    CHECK(echoes("module m(a, b = a * 2) echo(a, b);\nm(3);\nm(b = 1, a = 0);") ==
          std::vector<std::string>{"ECHO: 3, 6", "ECHO: 0, 1"});
    CHECK(error_of("module m(a) {}\nm(1, 2);") == "test.sdl:2:6: error: too many arguments for 'm' (takes 1)");
    CHECK(error_of("module m(a) {}\nm(z = 2);") == "test.sdl:2:3: error: unknown argument 'z' for 'm'");
    CHECK(error_of("nosuch(1);") == "test.sdl:1:1: error: unknown module 'nosuch'");
    CHECK(error_of("surface(\"x.dat\");") == "test.sdl:1:1: error: cannot find 'x.dat'");
}

TEST_CASE("children(), children(i) and $children", "[modules]") {
    const char* m = "module m() { echo($children); children(); }\n";
    CHECK(echoes(std::string(m) + "m() { cube(); sphere(); }") == std::vector<std::string>{"ECHO: 2"});
    CHECK(shape_of(std::string(m) + "m() { cube(); sphere(); }") == "U(U(box,sphere))");
    CHECK(shape_of("module second() children(1);\nsecond() { cube(); sphere(); cylinder(); }") == "U(sphere)");
    CHECK(shape_of("module pick() children([0, 2]);\npick() { cube(); sphere(); cylinder(); }") == "U(U(box,cylinder))");
    // Child-block assignments are visible to the children and not counted.
    CHECK(echoes("module m() { echo($children); children(); }\nm() { s = 2; echo(s); }") ==
          std::vector<std::string>{"ECHO: 1", "ECHO: 2"});
    // Children evaluate in the caller's scope.
    CHECK(echoes("module m() { v = 100; children(); }\nv = 1;\nm() echo(v);") == std::vector<std::string>{"ECHO: 1"});
    // Nested: children() inside a child list refers to the outer module's children.
    CHECK(shape_of("module inner() children();\nmodule outer() inner() children();\nouter() sphere();") == "U(sphere)");
    CHECK(error_of("children();") == "test.sdl:1:1: error: children() is only allowed inside a module");
    CHECK(error_of("module m() children(3);\nm() cube();") == "test.sdl:1:12: error: children: index 3 out of range (1 children)");
    CHECK(value_of("$children") == "0");
}

TEST_CASE("if, for, let, echo and assert statements", "[modules]") {
    CHECK(shape_of("if (1 > 0) cube(); else sphere();") == "U(box)");
    CHECK(shape_of("if (0) cube(); else sphere();") == "U(sphere)");
    CHECK(shape_of("if (0) cube();") == "U()");
    CHECK(shape_of("for (i = [0:2]) translate([i, 0, 0]) cube();") == "U(U(T(box),T(box),T(box)))");
    CHECK(shape_of("for (i = [0:1], j = [0:1]) cube();") == "U(U(box,box,box,box))");
    CHECK(shape_of("for (p = [[1, 0, 0], [0, 1, 0]]) translate(p) sphere();") == "U(U(T(sphere),T(sphere)))");
    CHECK(shape_of("for (i = [1:0]) cube();") == "U()");
    CHECK(shape_of("let (r = 2) sphere(r);") == "U(sphere)");
    CHECK(echoes("for (i = [0:2]) echo(i);") == std::vector<std::string>{"ECHO: 0", "ECHO: 1", "ECHO: 2"});
    CHECK(echoes("for (i = [0:1]) { j = i * 10; echo(j); }") == std::vector<std::string>{"ECHO: 0", "ECHO: 10"});
    CHECK(error_of("x = 3;\nassert(x < 2, str(\"x is \", x));") == "test.sdl:2:1: error: assertion failed: x is 3");
    CHECK(error_of("for (i = true) cube();") == "test.sdl:1:6: error: for: expected a range, a list or a string, got bool");
    // A string iterates over its characters (UTF-8 code points), as in OpenSCAD.
    CHECK(echoes("for (c = \"aé€\") echo(c);") == std::vector<std::string>{"ECHO: \"a\"", "ECHO: \"é\"", "ECHO: \"€\""});
    CHECK(echoes("for (c = \"\") echo(c);").empty());
    // difference() sees a for loop as one child (the union of its iterations).
    CHECK(shape_of("difference() { cube(); for (i = [0:1]) sphere(); }") == "U(D(box,U(sphere,sphere)))");
    CHECK(shape_of("union() {}") == "U(U())");
    CHECK(shape_of("{ cube(); sphere(); }") == "U(U(box,sphere))");
}

TEST_CASE("debug modifiers", "[modules]") {
    CHECK(shape_of("*cube();\nsphere();") == "U(sphere)");
    CHECK(shape_of("*nosuch();\nsphere();") == "U(sphere)");  // disabled: not evaluated
    CHECK(shape_of("%cube();\nsphere();") == "U(sphere)");    // background: dropped
    CHECK(shape_of("#cube();\nsphere();") == "U(box,sphere)");  // highlight: rendered normally
    CHECK(shape_of("sphere();\ntranslate([1, 0, 0]) !cube();\ncylinder();") == "U(box)");
    CHECK(error_of("%nosuch();") == "test.sdl:1:2: error: unknown module 'nosuch'");
}

TEST_CASE("debug modifiers on if, for and let", "[modules]") {
    CHECK(shape_of("*if (true) cube();\nsphere();") == "U(sphere)");
    CHECK(shape_of("*if (true) nosuch();\nsphere();") == "U(sphere)");
    CHECK(shape_of("%if (true) cube(); else cylinder();\nsphere();") == "U(sphere)");
    CHECK(shape_of("%if (false) cube(); else cylinder();\nsphere();") == "U(sphere)");
    CHECK(shape_of("#if (true) cube();\nsphere();") == "U(box,sphere)");
    CHECK(shape_of("sphere();\n!if (true) { cube(); cylinder(); }\n!sphere();") == "U(U(box,cylinder))");
    CHECK(shape_of("sphere();\nif (true) !if (true) cube();") == "U(box)");
    CHECK(shape_of("*for (i = [1:3]) cube(i);\nsphere();") == "U(sphere)");
    CHECK(shape_of("%for (i = [1:3]) cube(i);\nsphere();") == "U(sphere)");
    CHECK(shape_of("sphere();\n!let (a = 1) cube(a);") == "U(box)");
    CHECK(error_of("%if (nosuch) cube();") == "test.sdl:1:6: error: undefined name 'nosuch'");
}
