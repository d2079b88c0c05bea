#include "grammar/ast_print.hpp"

#include <charconv>

namespace kerf::ast {

// A string literal as written in source: quotes and \\ \" \n \t \r escaped.
void quoted(std::string& out, const std::string& text) {
    out += '"';
    for (char c : text) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            case '\r': out += "\\r"; break;
            default: out += c;
        }
    }
    out += '"';
}

namespace {
void print(std::string& out, const Expr& e);
void print(std::string& out, const Stmt& s);

std::string number_text(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
    return std::string(buf, r.ptr);
}

void print(std::string& out, const Binding& b) {
    if (b.name.empty()) {
        if (b.value) print(out, *b.value);
        return;
    }
    if (!b.value) {
        out += b.name;
        return;
    }
    out += "(= " + b.name + ' ';
    print(out, *b.value);
    out += ')';
}

void print_list(std::string& out, const std::vector<Binding>& bs) {
    out += '(';
    for (std::size_t i = 0; i < bs.size(); ++i) {
        if (i) out += ' ';
        print(out, bs[i]);
    }
    out += ')';
}

void print_args(std::string& out, const std::vector<Binding>& bs) {
    for (const auto& b : bs) {
        out += ' ';
        print(out, b);
    }
}

void print_items(std::string& out, const Expr& e) {
    for (const auto& i : e.items) {
        out += ' ';
        print(out, *i);
    }
}

void print(std::string& out, const Expr& e) {
    switch (e.kind) {
        case ExprKind::Number: out += number_text(e.number); return;
        case ExprKind::String: quoted(out, e.text); return;
        case ExprKind::Bool: out += e.number != 0 ? "true" : "false"; return;
        case ExprKind::Undef: out += "undef"; return;
        case ExprKind::Ident: out += e.text; return;
        case ExprKind::List: out += "(list"; print_items(out, e); break;
        case ExprKind::Range: out += "(range"; print_items(out, e); break;
        case ExprKind::Unary:
        case ExprKind::Binary: out += '(' + e.text; print_items(out, e); break;
        case ExprKind::Ternary: out += "(?:"; print_items(out, e); break;
        case ExprKind::Index: out += "(index"; print_items(out, e); break;
        case ExprKind::Member: out += "(. "; print(out, *e.items.at(0)); out += ' ' + e.text; break;
        case ExprKind::Call: out += "(call " + e.text; print_args(out, e.args); break;
        case ExprKind::Let: out += "(let "; print_list(out, e.bindings); print_items(out, e); break;
        case ExprKind::Echo: out += "(echo "; print_list(out, e.args); print_items(out, e); break;
        case ExprKind::Assert: out += "(assert "; print_list(out, e.args); print_items(out, e); break;
        case ExprKind::ListFor: out += "(list-for "; print_list(out, e.bindings); print_items(out, e); break;
        case ExprKind::Function: out += "(function "; print_list(out, e.bindings); print_items(out, e); break;
        case ExprKind::Apply: out += "(apply"; print_items(out, e); print_args(out, e.args); break;
        case ExprKind::ListForC:
            out += "(list-for-c ";
            print_list(out, e.bindings);
            out += ' ';
            print_list(out, e.args);
            print_items(out, e);
            break;
        case ExprKind::ListEach: out += "(list-each"; print_items(out, e); break;
        case ExprKind::ListIf: out += "(list-if"; print_items(out, e); break;
        case ExprKind::ListLet: out += "(list-let "; print_list(out, e.bindings); print_items(out, e); break;
    }
    out += ')';
}

void print_body(std::string& out, const std::vector<StmtPtr>& body) {
    for (const auto& s : body) {
        out += ' ';
        print(out, *s);
    }
}

const char* modifier_text(Modifier m) {
    switch (m) {
        case Modifier::None: return "";
        case Modifier::Disable: return "*";
        case Modifier::Root: return "!";
        case Modifier::Highlight: return "#";
        case Modifier::Background: return "%";
    }
    return "";
}

void print(std::string& out, const Stmt& s) {
    switch (s.kind) {
        case StmtKind::Assign:
            out += "(= " + s.name + ' ';
            print(out, *s.value);
            break;
        case StmtKind::FunctionDef:
            out += "(function " + s.name + ' ';
            print_list(out, s.params);
            out += ' ';
            print(out, *s.value);
            break;
        case StmtKind::ModuleDef:
            out += "(module " + s.name + ' ';
            print_list(out, s.params);
            print_body(out, s.body);
            break;
        case StmtKind::Instantiate:
            out += std::string(modifier_text(s.modifier)) + '(' + s.name;
            print_args(out, s.args);
            print_body(out, s.body);
            break;
        case StmtKind::If:
            out += std::string(modifier_text(s.modifier)) + "(if ";
            print(out, *s.value);
            out += " (then";
            print_body(out, s.body);
            out += ')';
            if (s.has_else) {
                out += " (else";
                print_body(out, s.else_body);
                out += ')';
            }
            break;
        case StmtKind::Block: out += "(block"; print_body(out, s.body); break;
        case StmtKind::Include: out += "(include "; quoted(out, s.name); break;
        case StmtKind::Use: out += "(use "; quoted(out, s.name); break;
        case StmtKind::Empty: out += "(empty"; break;
    }
    out += ')';
}
}  // namespace

std::string to_sexpr(const Expr& e) {
    std::string out;
    print(out, e);
    return out;
}

std::string to_sexpr(const Stmt& s) {
    std::string out;
    print(out, s);
    return out;
}

std::string to_sexpr(const Program& p) {
    std::string out;
    for (std::size_t i = 0; i < p.stmts.size(); ++i) {
        if (i) out += '\n';
        print(out, *p.stmts[i]);
    }
    return out;
}

}  // namespace kerf::ast
