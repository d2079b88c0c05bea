// The parser state: builds the AST from the grammar actions with explicit
// stacks (expressions, binding lists, names, open statements). Kept free of
// PEGTL so it compiles once, in builder.cpp; actions.hpp maps rules to these
// calls. The grammar guarantees the calls come in balanced order.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/ast.hpp"
#include "grammar/rules_nest.hpp"
#include "grammar/source.hpp"

namespace kerf::grammar {

class Builder {
public:
    Builder(std::shared_ptr<const SourceFile> file, std::size_t max_nesting);

    NestingCounter nesting;  // used by nest<> rules
    bool openscad = false;   // ParseOptions::openscad, read by the lexical rules
    // Expression trees may be this many times deeper than source nesting.
    static constexpr std::size_t kChainFactor = 16;

    SourceLoc loc(std::size_t line, std::size_t col) const;

    // The last non-empty whitespace (and comments) matched: where the token
    // before it ended. A missing `;` is reported there, at the end of the
    // statement that lacks it, not at the next line's first token.
    const char* gap_begin = nullptr;
    const char* gap_end = nullptr;

    // ---- expressions
    void number(std::string_view text, SourceLoc at);
    void string(std::string_view literal, SourceLoc at);  // literal with its quotes
    void boolean(bool value, SourceLoc at);
    void undef(SourceLoc at);
    void ident(std::string_view name, SourceLoc at);
    void op(std::string_view text);  // pending unary/binary operator
    void unary(SourceLoc at);
    void binary(SourceLoc at);
    void ternary(SourceLoc at);
    void index(SourceLoc at);
    void member_name(std::string_view name);
    void member(SourceLoc at);
    void mark_items();  // items of a list / range / list-if start here
    void list_kind(ast::ExprKind kind);  // List or Range, known at the closing `]`
    void list(SourceLoc at);              // builds that kind from the marked items
    void list_if(SourceLoc at);
    void c_style_for();  // the `for` header being read is `(init; cond; incr)`
    void for_header();   // a `for` header is complete (plain or C-style)
    void list_for(SourceLoc at);
    void list_let(SourceLoc at);
    void list_each(SourceLoc at);
    void let(SourceLoc at);
    void function_literal(SourceLoc at);  // pops the body and the parameter list
    void apply(SourceLoc at);             // pops the argument list and the callee
    void echo(SourceLoc at);
    void assert_(SourceLoc at);
    void push_name(std::string_view name, SourceLoc at);
    void call();  // pops the callee name and the argument list

    // ---- binding lists (arguments, parameters, for/let bindings)
    void open_bindings();
    void binding_name(std::string_view name, SourceLoc at);  // value follows, or none
    void binding_value();                                   // pops an expression
    void positional(SourceLoc at);                          // pops an expression

    // ---- statements
    void modifier(char c);
    void empty(SourceLoc at);
    void open(ast::StmtKind kind, std::string_view name, SourceLoc at);
    void set_name(std::string_view name);
    void set_args();    // pops a binding list into the open statement's args
    void set_params();  // ... into its params
    void set_value();   // pops an expression into the open statement's value
    void start_else();
    void close();
    void assign(SourceLoc at);
    void function_def(SourceLoc at);
    void path(std::string text);
    void include(ast::StmtKind kind, SourceLoc at);

    ast::Program finish();

private:
    struct Slot {
        ast::ExprPtr expr;
        std::uint32_t height;  // of the subtree: bounded like source nesting
    };
    struct BindingList {
        std::vector<ast::Binding> items;
        std::uint32_t height = 0;
    };
    struct Name {
        std::string text;
        SourceLoc loc;
    };

    ast::ExprPtr make(ast::ExprKind kind, SourceLoc at);
    void push(ast::ExprPtr e, std::uint32_t height);
    ast::ExprPtr pop(std::uint32_t& height);
    ast::ExprPtr pop();
    std::vector<ast::ExprPtr> pop_items(std::uint32_t& height);
    BindingList pop_bindings();
    Name pop_name();
    void append(ast::StmtPtr s);
    // A node of `kind` from the element on top and the binding list below it.
    void generator(ast::ExprKind kind, SourceLoc at);

    std::shared_ptr<const SourceFile> file_;
    std::vector<Slot> exprs_;
    std::vector<std::size_t> marks_;
    std::vector<BindingList> bindings_;  // scratch lists, [0, open_bindings_) in use
    std::size_t open_bindings_ = 0;
    std::vector<Name> names_;
    std::vector<std::string> ops_;
    std::vector<ast::StmtPtr> open_;  // open_[0] is the program's root block
    bool c_style_pending_ = false;
    std::vector<bool> for_kinds_;  // per open list `for`: C-style?
    std::string member_ = "x";
    ast::ExprKind list_kind_ = ast::ExprKind::List;
    ast::Modifier modifier_ = ast::Modifier::None;
    std::string path_;
};

}  // namespace kerf::grammar
