// Statement shapes (docs/spec.md §3): assignments, definitions, instantiations with
// children, modifiers, if/else, for, let, include/use, blocks.
#include <catch2/catch.hpp>

#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::parse;
using kerf::test::sx;
namespace ast = kerf::ast;

TEST_CASE("assignments and definitions", "[grammar][stmt]") {
    CHECK(sx("x = 1;") == "(= x 1)");
    CHECK(sx("$fn = 32;") == "(= $fn 32)");
    CHECK(sx("function f(a, b = 2) = a + b;") == "(function f (a (= b 2)) (+ a b))");
    CHECK(sx("function g() = 1;") == "(function g () 1)");
    CHECK(sx("module m(a, b = 2) { cube(a); }") == "(module m (a (= b 2)) (cube a))");
    CHECK(sx("module m() cube();") == "(module m () (cube))");
    CHECK(sx("module m();") == "(module m ())");

    auto p = parse("function f(a, b = 2) = a;");
    const auto& params = p.stmts.at(0)->params;
    REQUIRE(params.size() == 2);
    CHECK(params[0].name == "a");
    CHECK(params[0].value == nullptr);  // no default
    CHECK(params[1].name == "b");
    REQUIRE(params[1].value != nullptr);
    CHECK(params[1].value->number == 2);
}

TEST_CASE("instantiations and children", "[grammar][stmt]") {
    CHECK(sx("cube();") == "(cube)");
    CHECK(sx("cube(10, center = true);") == "(cube 10 (= center true))");
    CHECK(sx("translate([1, 0, 0]) cube();") == "(translate (list 1 0 0) (cube))");
    CHECK(sx("translate(v) rotate(a) sphere(1);") == "(translate v (rotate a (sphere 1)))");
    CHECK(sx("difference() { cube(10, center=true); sphere(6); }") ==
          "(difference (cube 10 (= center true)) (sphere 6))");
    CHECK(sx("union() { }") == "(union)");
    CHECK(sx("union() { ; }") == "(union (empty))");
    CHECK(sx("children();") == "(children)");
    CHECK(sx("children(0);") == "(children 0)");
    CHECK(sx("echo(\"a\", x = 1);") == "(echo \"a\" (= x 1))");
    CHECK(sx("assert(x > 0, \"msg\");") == "(assert (> x 0) \"msg\")");
    CHECK(sx("u() { x = 1; { a(); } }") == "(u (= x 1) (block (a)))");

    auto p = parse("union() { a(); b(); }");
    const auto& s = *p.stmts.at(0);
    CHECK(s.kind == ast::StmtKind::Instantiate);
    CHECK(s.name == "union");
    CHECK(s.body.size() == 2);
}

TEST_CASE("for and let statements are instantiations with bindings", "[grammar][stmt]") {
    CHECK(sx("for (i = [0:15]) rotate([0, 0, 22.5*i]) cube();") ==
          "(for (= i (range 0 15)) (rotate (list 0 0 (* 22.5 i)) (cube)))");
    CHECK(sx("for (i = r, j = s) { a(i); b(j); }") == "(for (= i r) (= j s) (a i) (b j))");
    CHECK(sx("let (a = 1, b = a + 1) cube(b);") == "(let (= a 1) (= b (+ a 1)) (cube b))");
    auto p = parse("for (i = r, j = s) x();");
    const auto& s = *p.stmts.at(0);
    CHECK(s.kind == ast::StmtKind::Instantiate);
    CHECK(s.name == "for");
    REQUIRE(s.args.size() == 2);
    CHECK(s.args[0].name == "i");
    CHECK(s.args[1].name == "j");
}

TEST_CASE("if / else", "[grammar][stmt]") {
    CHECK(sx("if (a) b();") == "(if a (then (b)))");
    CHECK(sx("if (a) b(); else c();") == "(if a (then (b)) (else (c)))");
    CHECK(sx("if (a) { b(); c(); } else { d(); }") == "(if a (then (b) (c)) (else (d)))");
    CHECK(sx("if (a) b(); else if (c) d(); else e();") == "(if a (then (b)) (else (if c (then (d)) (else (e)))))");
    CHECK(sx("if (a) if (b) c(); else d();") == "(if a (then (if b (then (c)) (else (d)))))");
    auto p = parse("if (a) b(); else c();");
    CHECK(p.stmts.at(0)->has_else);
    CHECK_FALSE(parse("if (a) b();").stmts.at(0)->has_else);
    CHECK(sx("if (a) {} else {}") == "(if a (then) (else))");
    CHECK(parse("if (a) {} else {}").stmts.at(0)->has_else);
}

TEST_CASE("debug modifiers", "[grammar][stmt]") {
    CHECK(sx("!cube();") == "!(cube)");
    CHECK(sx("#cube();") == "#(cube)");
    CHECK(sx("%cube();") == "%(cube)");
    CHECK(sx("*cube();") == "*(cube)");
    CHECK(sx("translate(v) #cube();") == "(translate v #(cube))");
    CHECK(sx("#!cube();") == "#(cube)");    // leftmost kept
    CHECK(sx("#*cube();") == "*(cube)");    // disable wins
    CHECK(sx("%if (a) b();") == "%(if a (then (b)))");
    CHECK(sx("* for (i = a) b();") == "*(for (= i a) (b))");
    auto p = parse("# cube();");
    CHECK(p.stmts.at(0)->modifier == ast::Modifier::Highlight);
}

TEST_CASE("blocks, empty statements, include and use", "[grammar][stmt]") {
    CHECK(sx("{ a(); b(); }") == "(block (a) (b))");
    CHECK(sx("{ { } }") == "(block (block))");
    CHECK(sx(";") == "(empty)");
    CHECK(sx("include <lib/shapes.sdl>") == "(include \"lib/shapes.sdl\")");
    CHECK(sx("include \"my lib.sdl\";") == "(include \"my lib.sdl\")\n(empty)");
    CHECK(sx("use <colors.sdl> x = 1;") == "(use \"colors.sdl\")\n(= x 1)");
    CHECK(sx("use \"a\\\\b.sdl\"") == "(use \"a\\\\b.sdl\")");
    CHECK(sx("") == "");
    CHECK(sx("  // only a comment\n/* and another */  ") == "");
}

TEST_CASE("an OpenSCAD-style script", "[grammar][stmt]") {
    const char* script = R"(// grooved sphere
$fn = 64;
module pair(r = 0.1) {
    translate([0, 0, 0.374]) scale(0.9) torus(1, r);
    rotate([0, 180, 0]) translate([0, 0, 0.374]) scale(0.9) torus(1, r);
}
difference() {
    sphere(1);
    union() { pair(); rotate([0, 90, 0]) pair(); rotate([90, 0, 0]) pair(); }
}
)";
    auto p = parse(script);
    REQUIRE(p.stmts.size() == 3);
    CHECK(p.stmts[0]->kind == ast::StmtKind::Assign);
    CHECK(p.stmts[1]->kind == ast::StmtKind::ModuleDef);
    CHECK(p.stmts[1]->body.size() == 2);
    CHECK(p.stmts[2]->kind == ast::StmtKind::Instantiate);
    CHECK(p.stmts[2]->body.size() == 2);
    CHECK(p.file->path == "t.sdl");
}
