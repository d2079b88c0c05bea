// The abstract syntax tree of a .sdl script (docs/spec.md §1–§3). Plain owning
// structs: every node carries its SourceLoc, nothing points into the input
// buffer, so the tree outlives the parse. One fat node type per category
// (Expr, Stmt) keeps the parser's actions and the interpreter's switch simple.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "grammar/source.hpp"

namespace kerf::ast {

struct Expr;
struct Stmt;
using ExprPtr = std::unique_ptr<Expr>;
using StmtPtr = std::unique_ptr<Stmt>;

// `name = value` in a call (`f(b = 3)`), in `let (...)`, `for (...)`, or a
// parameter `a = default` of a definition. `name` is empty for a positional
// argument; `value` is null for a parameter without a default.
struct Binding {
    std::string name;
    ExprPtr value;
    SourceLoc loc;
};

enum class ExprKind {
    Number,     // number
    String,     // text
    Bool,       // number != 0
    Undef,
    Ident,      // text = name (may start with '$')
    List,       // items = elements; each may be a generator (ListFor/ListIf/ListLet)
    Range,      // items = {start, end} or {start, step, end}
    Unary,      // text = "-", "+", "!"; items = {operand}
    Binary,     // text = operator ("+", "==", "&&", "^", ...); items = {lhs, rhs}
    Ternary,    // items = {cond, then, else}
    Index,      // items = {object, index}
    Member,     // text = "x" | "y" | "z"; items = {object}
    Call,       // text = callee name; args = arguments
    Let,        // bindings; items = {body}
    Echo,       // args; items = {body}            (`echo(...) expr`)
    Assert,     // args; items = {body}            (`assert(c, "m") expr`)
    Function,   // bindings = parameters; items = {body}   (`function (x) x * 2`)
    Apply,      // items = {callee}; args              (`f(1)(2)`, `fs[0](3)`)
    // Generators, only as list elements:
    ListFor,    // bindings (several = nested loops); items = {element}
    ListForC,   // `for (init; cond; incr)`: bindings = init, args = incr; items = {cond, element}
    ListIf,     // items = {cond, then} or {cond, then, else}
    ListLet,    // bindings; items = {element}
    ListEach,   // items = {element}: its lists, ranges and strings spliced (`each v`)
};

struct Expr {
    ExprKind kind = ExprKind::Undef;
    SourceLoc loc;
    double number = 0;
    std::string text;
    std::vector<ExprPtr> items;
    std::vector<Binding> args;      // Call, Echo, Assert, Apply, ListForC
    std::vector<Binding> bindings;  // Let, ListFor, ListForC, ListLet, Function
};

enum class StmtKind {
    Assign,       // name = value;
    FunctionDef,  // function name(params) = value;
    ModuleDef,    // module name(params) { body }
    Instantiate,  // name(args) child;  name(args) { body }  name(args);
                  // `for`, `let`, `echo`, `assert`, `children` are instantiations
                  // too, as in OpenSCAD: `for (i = r, j = s)` has args i, j.
    If,           // if (value) body else else_body
    Block,        // { body }   (an implicit union)
    Include,      // include <name>   (name = path as written)
    Use,          // use <name>
    Empty,        // a lone `;`
};

// Debug modifiers in front of an instantiation, as in OpenSCAD.
enum class Modifier { None, Disable /* * */, Root /* ! */, Highlight /* # */, Background /* % */ };

struct Stmt {
    StmtKind kind = StmtKind::Empty;
    SourceLoc loc;
    std::string name;
    ExprPtr value;
    std::vector<Binding> params;  // FunctionDef, ModuleDef
    std::vector<Binding> args;    // Instantiate
    std::vector<StmtPtr> body;    // ModuleDef, Instantiate children, If then, Block
    std::vector<StmtPtr> else_body;
    bool has_else = false;
    Modifier modifier = Modifier::None;
    // FunctionDef: whether the body calls the function itself in tail
    // position (the evaluator's cache, filled on the first call: -1 not
    // known yet), so that only such functions take the tail-call loop.
    mutable signed char self_tail_call = -1;
    // Instantiate: what the name calls unless a user module of that name is
    // in scope (the evaluator's cache, filled on the first evaluation: -1
    // not known yet; interpreter/eval_stmt.cpp, `dispatch`). The name never
    // changes, so neither does the answer; comparing it against every
    // control name and searching the built-in table was a quarter of
    // evaluating a loop of translated spheres (docs/performance.md).
    mutable std::int16_t dispatch = -1;
};

struct Program {
    std::shared_ptr<const SourceFile> file;
    std::vector<StmtPtr> stmts;
};

}  // namespace kerf::ast
