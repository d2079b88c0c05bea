// OpenSCAD 2021's expression printer, reproduced from its output (checked
// with `openscad -o out.echo` on echo(function ...) of every expression
// kind, tests/scripts/openscad/function_literals.scad).
#include "interpreter/expr_text.hpp"

#include "grammar/ast_print.hpp"
#include "interpreter/value.hpp"

namespace kerf {
namespace {

using ast::ExprKind;

void print(std::string& out, const ast::Expr& e);

void bindings(std::string& out, const std::vector<ast::Binding>& list) {
    bool first = true;
    for (const ast::Binding& b : list) {
        if (!first) out += ", ";
        first = false;
        if (!b.name.empty()) {
            out += b.name;
            if (b.value) out += " = ";
        }
        if (b.value) print(out, *b.value);
    }
}

bool is_generator(const ast::Expr& e) {
    return e.kind == ExprKind::ListFor || e.kind == ExprKind::ListForC || e.kind == ExprKind::ListIf ||
           e.kind == ExprKind::ListEach ||
           (e.kind == ExprKind::ListLet && is_generator(*e.items[0]));
}

// The element a generator wraps, in parentheses as OpenSCAD prints it.
void wrapped(std::string& out, const ast::Expr& e) {
    out += '(';
    print(out, e);
    out += ')';
}

void list_for(std::string& out, const ast::Expr& e, std::size_t k) {
    out += "for(";
    const ast::Binding& b = e.bindings[k];
    out += b.name + " = ";
    if (b.value) print(out, *b.value);
    out += ") (";
    if (k + 1 < e.bindings.size()) list_for(out, e, k + 1);
    else print(out, *e.items[0]);
    out += ')';
}

void print(std::string& out, const ast::Expr& e) {
    switch (e.kind) {
        case ExprKind::Number: out += format_number(e.number); return;
        case ExprKind::String: ast::quoted(out, e.text); return;
        case ExprKind::Bool: out += e.number != 0 ? "true" : "false"; return;
        case ExprKind::Undef: out += "undef"; return;
        case ExprKind::Ident: out += e.text; return;
        case ExprKind::List:
        case ExprKind::Range:
            out += '[';
            for (std::size_t i = 0; i < e.items.size(); ++i) {
                if (i) out += e.kind == ExprKind::List ? ", " : " : ";
                print(out, *e.items[i]);
            }
            out += ']';
            return;
        case ExprKind::Unary:
            if (e.text != "+") out += e.text;  // OpenSCAD's parser drops a unary +
            print(out, *e.items[0]);
            return;
        case ExprKind::Binary:
            out += '(';
            print(out, *e.items[0]);
            out += ' ' + e.text + ' ';
            print(out, *e.items[1]);
            out += ')';
            return;
        case ExprKind::Ternary:
            out += '(';
            print(out, *e.items[0]);
            out += " ? ";
            print(out, *e.items[1]);
            out += " : ";
            print(out, *e.items[2]);
            out += ')';
            return;
        case ExprKind::Index:
            print(out, *e.items[0]);
            out += '[';
            print(out, *e.items[1]);
            out += ']';
            return;
        case ExprKind::Member:
            print(out, *e.items[0]);
            out += '.' + e.text;
            return;
        case ExprKind::Call:
            out += e.text + '(';
            bindings(out, e.args);
            out += ')';
            return;
        case ExprKind::Apply:
            if (e.items[0]->kind == ExprKind::Ident) print(out, *e.items[0]);
            else wrapped(out, *e.items[0]);
            out += '(';
            bindings(out, e.args);
            out += ')';
            return;
        case ExprKind::Let:
        case ExprKind::ListLet:
            out += "let(";
            bindings(out, e.bindings);
            out += ") ";
            if (is_generator(*e.items[0])) wrapped(out, *e.items[0]);
            else print(out, *e.items[0]);
            return;
        case ExprKind::Echo:
        case ExprKind::Assert:
            out += e.kind == ExprKind::Echo ? "echo(" : "assert(";
            bindings(out, e.args);
            out += ") ";
            print(out, *e.items[0]);
            return;
        case ExprKind::Function:
            out += "function(";
            bindings(out, e.bindings);
            out += ") ";
            print(out, *e.items[0]);
            return;
        case ExprKind::ListFor: list_for(out, e, 0); return;
        case ExprKind::ListForC:
            out += "for(";
            bindings(out, e.bindings);
            out += ';';
            print(out, *e.items[0]);
            out += ';';
            bindings(out, e.args);
            out += ") ";
            print(out, *e.items[1]);
            return;
        case ExprKind::ListEach:
            out += "each ";
            wrapped(out, *e.items[0]);
            return;
        case ExprKind::ListIf:
            out += "if(";
            print(out, *e.items[0]);
            out += ") ";
            wrapped(out, *e.items[1]);
            if (e.items.size() > 2) {
                out += " else ";
                wrapped(out, *e.items[2]);
            }
            return;
    }
}

}  // namespace

std::string openscad_text(const ast::Expr& e) {
    std::string out;
    print(out, e);
    return out;
}

}  // namespace kerf
