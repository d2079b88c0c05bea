// Expression shapes and precedence (docs/spec.md §2), checked through the
// s-expression printer: each expected string is written by hand from the
// spec's precedence table, not taken from parser output.
#include <catch2/catch.hpp>

#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::ex;

TEST_CASE("literals and names", "[grammar][expr]") {
    CHECK(ex("12") == "12");
    CHECK(ex("1.5") == "1.5");
    CHECK(ex(".5") == "0.5");
    CHECK(ex("1e-3") == "0.001");
    CHECK(ex("2.5E+4") == "25000");
    CHECK(ex("true") == "true");
    CHECK(ex("false") == "false");
    CHECK(ex("undef") == "undef");
    CHECK(ex("abc_1") == "abc_1");
    CHECK(ex("$fn") == "$fn");
    CHECK(ex("_x") == "_x");
    CHECK(ex("\"hi\"") == "\"hi\"");
    CHECK(ex("truex") == "truex");  // a keyword prefix is still a name
    CHECK(ex("iffy") == "iffy");
}

TEST_CASE("binary precedence, lowest to highest", "[grammar][expr]") {
    CHECK(ex("1 + 2 * 3") == "(+ 1 (* 2 3))");
    CHECK(ex("1 * 2 + 3") == "(+ (* 1 2) 3)");
    CHECK(ex("a - b - c") == "(- (- a b) c)");
    CHECK(ex("a / b % c * d") == "(* (% (/ a b) c) d)");
    CHECK(ex("a < b + 1") == "(< a (+ b 1))");
    CHECK(ex("a <= b") == "(<= a b)");
    CHECK(ex("a >= b") == "(>= a b)");
    CHECK(ex("a > b") == "(> a b)");
    CHECK(ex("a == b < c") == "(== a (< b c))");
    CHECK(ex("a != b") == "(!= a b)");
    CHECK(ex("a && b == c") == "(&& a (== b c))");
    CHECK(ex("a || b && c") == "(|| a (&& b c))");
    CHECK(ex("a || b || c") == "(|| (|| a b) c)");
    CHECK(ex("a ? b : c || d") == "(?: a b (|| c d))");
    CHECK(ex("a || b ? c : d") == "(?: (|| a b) c d)");
    CHECK(ex("a ? b : c ? d : e") == "(?: a b (?: c d e))");
    CHECK(ex("a ? b ? c : d : e") == "(?: a (?: b c d) e)");
    CHECK(ex("(1 + 2) * 3") == "(* (+ 1 2) 3)");
}

TEST_CASE("unary, power and postfix", "[grammar][expr]") {
    CHECK(ex("-2^2") == "(- (^ 2 2))");
    CHECK(ex("2^3^2") == "(^ 2 (^ 3 2))");
    CHECK(ex("2^-1") == "(^ 2 (- 1))");
    CHECK(ex("-a * b") == "(* (- a) b)");
    CHECK(ex("!a && b") == "(&& (! a) b)");
    CHECK(ex("+a") == "(+ a)");
    CHECK(ex("- - a") == "(- (- a))");
    CHECK(ex("a - -b") == "(- a (- b))");
    CHECK(ex("a[1]") == "(index a 1)");
    CHECK(ex("a[1][2]") == "(index (index a 1) 2)");
    CHECK(ex("-a[0]^2") == "(- (^ (index a 0) 2))");
    CHECK(ex("p.x") == "(. p x)");
    CHECK(ex("p[0].y + q.z") == "(+ (. (index p 0) y) (. q z))");
    CHECK(ex("f(1)[0]") == "(index (call f 1) 0)");
    CHECK(ex("[1, 2].x") == "(. (list 1 2) x)");
}

TEST_CASE("calls with positional and named arguments", "[grammar][expr]") {
    CHECK(ex("f()") == "(call f)");
    CHECK(ex("f(1, 2)") == "(call f 1 2)");
    CHECK(ex("f(1, b = 2)") == "(call f 1 (= b 2))");
    CHECK(ex("f(a == 2)") == "(call f (== a 2))");
    CHECK(ex("f(g(h(1)), $fn = 8,)") == "(call f (call g (call h 1)) (= $fn 8))");
    CHECK(ex("max([1, 2])") == "(call max (list 1 2))");
}

TEST_CASE("lists and ranges", "[grammar][expr]") {
    CHECK(ex("[]") == "(list)");
    CHECK(ex("[1]") == "(list 1)");
    CHECK(ex("[1, [2, \"a\"], true,]") == "(list 1 (list 2 \"a\") true)");
    CHECK(ex("[0:10]") == "(range 0 10)");
    CHECK(ex("[0 : 2 : 10]") == "(range 0 2 10)");
    CHECK(ex("[-1 : n - 1]") == "(range (- 1) (- n 1))");
    CHECK(ex("[a ? 1 : 2 : 5]") == "(range (?: a 1 2) 5)");
}

TEST_CASE("list comprehensions", "[grammar][expr]") {
    CHECK(ex("[for (i = [0:9]) i*i]") == "(list (list-for ((= i (range 0 9))) (* i i)))");
    CHECK(ex("[for (i = a, j = b) [i, j]]") == "(list (list-for ((= i a) (= j b)) (list i j)))");
    CHECK(ex("[for (i = a) if (i > 0) i]") == "(list (list-for ((= i a)) (list-if (> i 0) i)))");
    CHECK(ex("[if (c) 1 else 2]") == "(list (list-if c 1 2))");
    CHECK(ex("[for (i = a) let (j = i * 2) j]") == "(list (list-for ((= i a)) (list-let ((= j (* i 2))) j)))");
    CHECK(ex("[0, for (i = a) i, 9]") == "(list 0 (list-for ((= i a)) i) 9)");
    CHECK(ex("[for (i = a) for (j = b) i + j]") == "(list (list-for ((= i a)) (list-for ((= j b)) (+ i j))))");
    CHECK(ex("[if (a) if (b) 1 else 2]") == "(list (list-if a (list-if b 1 2)))");  // else binds innermost
}

TEST_CASE("let, echo and assert as expression prefixes", "[grammar][expr]") {
    CHECK(ex("let (a = 1, b = a + 1) a * b") == "(let ((= a 1) (= b (+ a 1))) (* a b))");
    CHECK(ex("1 + let (a = 1) a * 2") == "(+ 1 (let ((= a 1)) (* a 2)))");
    CHECK(ex("echo(\"v\", v) v + 1") == "(echo (\"v\" v) (+ v 1))");
    CHECK(ex("assert(n > 0, \"bad\") n") == "(assert ((> n 0) \"bad\") n)");
    CHECK(ex("echo") == "echo");  // without '(' it is a plain name
}

TEST_CASE("comments and whitespace anywhere between tokens", "[grammar][expr]") {
    CHECK(ex("1 /* c */ + // line\n 2") == "(+ 1 2)");
    CHECK(ex("f /*a*/ ( /*b*/ 1 /*c*/ )") == "(call f 1)");
    CHECK(ex("a/**/[0]") == "(index a 0)");
    CHECK(ex("1\r\n+\t2") == "(+ 1 2)");
}
