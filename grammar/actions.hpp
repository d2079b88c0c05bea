// Grammar actions: map successful rules to Builder calls. A node's location
// is the start of the rule that builds it: its first token, except that
// operator nodes (Binary, Ternary, Index, Member) are located at their
// operator (`+`, `?`, `[`, `.`) so evaluation errors point at the operation
// that failed, and an instantiation is located at its name (after any
// debug modifiers).
#pragma once
#include "grammar/builder.hpp"
#include "grammar/literals.hpp"
#include "grammar/rules_stmt.hpp"

namespace kerf::grammar {

template <typename Input>
SourceLoc loc_of(const Input& in, const Builder& b) {
    return b.loc(in.iterator().line, in.iterator().column);
}

template <typename Rule>
struct action : pg::nothing<Rule> {};

// A rule whose action is `f(builder, location)`.
#define KERF_AT(rule, call)                                   \
    template <>                                               \
    struct action<rule> {                                     \
        template <typename Input>                             \
        static void apply(const Input& in, Builder& b) {      \
            [[maybe_unused]] const SourceLoc at = loc_of(in, b); \
            call;                                             \
        }                                                     \
    }

// ---- expressions
KERF_AT(number_lit, b.number(in.string_view(), at));
KERF_AT(string_lit, b.string(in.string_view(), at));
KERF_AT(true_lit, b.boolean(true, at));
KERF_AT(false_lit, b.boolean(false, at));
KERF_AT(undef_lit, b.undef(at));
KERF_AT(ident_name, b.ident(in.string_view(), at));
KERF_AT(callee, b.push_name(in.string_view(), at));
KERF_AT(call_expr, b.call());
KERF_AT(args_open, b.open_bindings());
KERF_AT(arg_name, b.binding_name(in.string_view(), at));
KERF_AT(named_arg, b.binding_value());
KERF_AT(positional_arg, b.positional(at));
KERF_AT(binding_name, b.binding_name(in.string_view(), at));
KERF_AT(binding, b.binding_value());
KERF_AT(unary_op, b.op(in.string_view()));
KERF_AT(pow_op, b.op(in.string_view()));
KERF_AT(mul_op, b.op(in.string_view()));
KERF_AT(add_op, b.op(in.string_view()));
KERF_AT(rel_op, b.op(in.string_view()));
KERF_AT(eq_op, b.op(in.string_view()));
KERF_AT(and_op, b.op(in.string_view()));
KERF_AT(or_op, b.op(in.string_view()));
KERF_AT(unary_prefixed, b.unary(at));
KERF_AT(power_tail, b.binary(at));
KERF_AT(mul_tail, b.binary(at));
KERF_AT(add_tail, b.binary(at));
KERF_AT(rel_tail, b.binary(at));
KERF_AT(eq_tail, b.binary(at));
KERF_AT(and_tail, b.binary(at));
KERF_AT(or_tail, b.binary(at));
KERF_AT(ternary_tail, b.ternary(at));
KERF_AT(index_op, b.index(at));
KERF_AT(member_name, b.member_name(in.string_view()));
KERF_AT(member_op, b.member(at));
KERF_AT(list_open, b.mark_items());
KERF_AT(list_empty, b.list_kind(ast::ExprKind::List));
KERF_AT(list_tail, b.list_kind(ast::ExprKind::List));
KERF_AT(range_tail, b.list_kind(ast::ExprKind::Range));
KERF_AT(list_expr, b.list(at));
KERF_AT(cfor_incr_open, b.open_bindings());
KERF_AT(cfor_tail, b.c_style_for());
KERF_AT(for_bindings, b.for_header());
KERF_AT(gen_for, b.list_for(at));
KERF_AT(gen_if_kw, b.mark_items());
KERF_AT(gen_if, b.list_if(at));
KERF_AT(gen_let, b.list_let(at));
KERF_AT(gen_each, b.list_each(at));
KERF_AT(let_expr, b.let(at));
KERF_AT(function_lit, b.function_literal(at));
KERF_AT(call_op, b.apply(at));
KERF_AT(empty_body, b.undef(at));
KERF_AT(echo_expr, b.echo(at));
KERF_AT(assert_expr, b.assert_(at));

// ---- whitespace: remembered for the location of a missing `;`
template <>
struct action<ws> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        if (in.begin() == in.end()) return;
        b.gap_begin = in.begin();
        b.gap_end = in.end();
    }
};

// ---- statements
KERF_AT(empty_stmt, b.empty(at));
KERF_AT(block_open, b.open(ast::StmtKind::Block, {}, at));
KERF_AT(block_stmt, b.close());
KERF_AT(modifier, b.modifier(in.peek_char()));
KERF_AT(inst_name, b.open(ast::StmtKind::Instantiate, in.string_view(), at));
KERF_AT(stmt_args, b.set_args());
KERF_AT(inst_stmt, b.close());
KERF_AT(for_kw, b.open(ast::StmtKind::Instantiate, "for", at));
KERF_AT(let_kw, b.open(ast::StmtKind::Instantiate, "let", at));
KERF_AT(stmt_bindings, b.set_args());
KERF_AT(for_stmt, b.close());
KERF_AT(let_stmt, b.close());
KERF_AT(if_kw, b.open(ast::StmtKind::If, {}, at));
KERF_AT(if_cond, b.set_value());
KERF_AT(else_kw, b.start_else());
KERF_AT(if_stmt, b.close());
KERF_AT(param_name, b.binding_name(in.string_view(), at));
KERF_AT(param_default, b.binding_value());
KERF_AT(module_kw, b.open(ast::StmtKind::ModuleDef, {}, at));
KERF_AT(module_name, b.set_name(in.string_view()));
KERF_AT(module_params, b.set_params());
KERF_AT(module_def, b.close());
KERF_AT(function_name, b.push_name(in.string_view(), at));
KERF_AT(function_def, b.function_def(at));
KERF_AT(assign_name, b.push_name(in.string_view(), at));
KERF_AT(assign_stmt, b.assign(at));
KERF_AT(path_text, b.path(in.string()));
KERF_AT(empty_path, b.path(std::string()));
KERF_AT(quoted_path, b.path(decode_string(in.string_view())));
KERF_AT(include_stmt, b.include(ast::StmtKind::Include, at));
KERF_AT(use_stmt, b.include(ast::StmtKind::Use, at));

#undef KERF_AT

}  // namespace kerf::grammar
