// Source locations of AST nodes: 1-based line and byte column of the first
// token, operators at their operator, instantiations at their name.
#include <catch2/catch.hpp>

#include "tests/grammar/grammar_test_util.hpp"

using kerf::test::parse;
namespace ast = kerf::ast;

namespace {
std::string at(const kerf::SourceLoc& l) { return std::to_string(l.line) + ":" + std::to_string(l.col); }
}  // namespace

TEST_CASE("expression locations", "[grammar][loc]") {
    //                 123456789012345678901234567890
    auto p = parse("x = -a + f(1, b = [2:3])[0].x;");
    const ast::Stmt& s = *p.stmts.at(0);
    CHECK(at(s.loc) == "1:1");
    const ast::Expr& plus = *s.value;
    CHECK(plus.kind == ast::ExprKind::Binary);
    CHECK(at(plus.loc) == "1:8");
    const ast::Expr& neg = *plus.items[0];
    CHECK(at(neg.loc) == "1:5");
    CHECK(at(neg.items[0]->loc) == "1:6");
    const ast::Expr& member = *plus.items[1];
    CHECK(member.kind == ast::ExprKind::Member);
    CHECK(at(member.loc) == "1:28");
    const ast::Expr& index = *member.items[0];
    CHECK(at(index.loc) == "1:25");
    const ast::Expr& call = *index.items[0];
    CHECK(call.kind == ast::ExprKind::Call);
    CHECK(at(call.loc) == "1:10");
    CHECK(at(call.args[0].loc) == "1:12");  // positional: its expression
    CHECK(at(call.args[1].loc) == "1:15");  // named: its name
    CHECK(at(call.args[1].value->loc) == "1:19");
    CHECK(at(index.items[1]->loc) == "1:26");
}

TEST_CASE("ternary, list, comprehension and prefix locations", "[grammar][loc]") {
    //                 1234567890123456789012345678901234567890123456
    auto p = parse("y = c ? [for (i = r) if (i) i] : let (a = 1) a;");
    const ast::Expr& t = *p.stmts.at(0)->value;
    CHECK(t.kind == ast::ExprKind::Ternary);
    CHECK(at(t.loc) == "1:7");
    const ast::Expr& list = *t.items[1];
    CHECK(at(list.loc) == "1:9");
    const ast::Expr& gen = *list.items.at(0);
    CHECK(gen.kind == ast::ExprKind::ListFor);
    CHECK(at(gen.loc) == "1:10");
    CHECK(at(gen.bindings.at(0).loc) == "1:15");
    CHECK(at(gen.items.at(0)->loc) == "1:22");
    const ast::Expr& let = *t.items[2];
    CHECK(let.kind == ast::ExprKind::Let);
    CHECK(at(let.loc) == "1:34");
}

TEST_CASE("statement locations", "[grammar][loc]") {
    const char* text =
        "module m(a) {\n"          // 1
        "  #cube(a);\n"            // 2
        "}\n"                      // 3
        "function f() = 1;\n"      // 4
        "if (x) { ; } else y();\n" // 5
        "  for (i = r) { }\n"      // 6
        "include <a.sdl>\n"        // 7
        "\t{ z(); }\n";            // 8
    auto p = parse(text);
    REQUIRE(p.stmts.size() == 6);
    CHECK(at(p.stmts[0]->loc) == "1:1");
    CHECK(at(p.stmts[0]->params.at(0).loc) == "1:10");
    CHECK(at(p.stmts[0]->body.at(0)->loc) == "2:4");  // the name, after the modifier
    CHECK(at(p.stmts[1]->loc) == "4:1");
    CHECK(at(p.stmts[2]->loc) == "5:1");
    CHECK(at(p.stmts[2]->value->loc) == "5:5");
    CHECK(at(p.stmts[2]->body.at(0)->loc) == "5:10");
    CHECK(at(p.stmts[2]->else_body.at(0)->loc) == "5:19");
    CHECK(at(p.stmts[3]->loc) == "6:3");
    CHECK(at(p.stmts[4]->loc) == "7:1");
    CHECK(at(p.stmts[5]->loc) == "8:2");  // a tab is one byte
    CHECK(at(p.stmts[5]->body.at(0)->loc) == "8:4");
    CHECK(p.stmts[5]->loc.file == p.file);
}

TEST_CASE("line counting across comments, strings and CRLF", "[grammar][loc]") {
    auto p = parse("/* one\ntwo */ a = \"x\ny\";\r\n// c\r\n  b = 1;");
    REQUIRE(p.stmts.size() == 2);
    CHECK(at(p.stmts[0]->loc) == "2:8");
    CHECK(at(p.stmts[1]->loc) == "5:3");
}
