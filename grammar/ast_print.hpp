// A compact s-expression rendering of the AST, for tests and `kerf dump
// --ast`. Examples: `(+ 1 (* 2 3))`, `(call f 1 (= b 2))`, `(list 1 2)`,
// `(range 0 1 9)`, `(list (list-for ((= i (range 0 9))) (* i i)))`, statements
// `(= x 1)`, `(cube 10 (= center true))`, `(translate (list 1 0 0) (cube))`,
// `(if c (then ...) (else ...))`, `(module m (a (= b 2)) ...)`.
#pragma once
#include <string>

#include "grammar/ast.hpp"

namespace kerf::ast {

std::string to_sexpr(const Expr& e);
std::string to_sexpr(const Stmt& s);
// Appends text as a quoted string literal, escaping \ " and \n \t \r
// (also OpenSCAD's way of printing a string inside an expression).
void quoted(std::string& out, const std::string& text);
// Top-level statements separated by newlines.
std::string to_sexpr(const Program& p);

}  // namespace kerf::ast
