// What a failed `must<>` says: one message per rule that can be required.
// tao::pegtl::must_if checks at compile time that every required rule has
// an entry here, so no user ever sees a demangled rule name.
#pragma once
#include "grammar/rules_stmt.hpp"

namespace kerf::grammar {

template <typename Rule>
inline constexpr const char* error_message = nullptr;

#define KERF_EXPECT(rule, text) \
    template <>                 \
    inline constexpr const char* error_message<rule> = "expected " text

KERF_EXPECT(expr, "expression");
KERF_EXPECT(if_cond, "expression");
KERF_EXPECT(unary, "expression");
KERF_EXPECT(mul_expr, "expression");
KERF_EXPECT(add_expr, "expression");
KERF_EXPECT(rel_expr, "expression");
KERF_EXPECT(eq_expr, "expression");
KERF_EXPECT(and_expr, "expression");
KERF_EXPECT(list_element, "expression");
KERF_EXPECT(generator, "for, if or each");
KERF_EXPECT(prefix_body, "expression");
KERF_EXPECT(list_next, "expression");
KERF_EXPECT(arg_next, "expression");
KERF_EXPECT(semi, "';'");
KERF_EXPECT(colon, "':'");
KERF_EXPECT(assign_eq, "'='");
KERF_EXPECT(lparen, "'('");
KERF_EXPECT(rparen, "')'");
KERF_EXPECT(rbracket, "']'");
KERF_EXPECT(rbrace, "'}'");
KERF_EXPECT(call_args, "'('");
KERF_EXPECT(stmt_args, "'('");
KERF_EXPECT(bind_list, "'('");
KERF_EXPECT(stmt_bindings, "'('");
KERF_EXPECT(for_bindings, "'('");
KERF_EXPECT(for_header_end, "')'");
KERF_EXPECT(cfor_semi, "';'");
KERF_EXPECT(cfor_cond, "expression");
KERF_EXPECT(cfor_incr, "name");
KERF_EXPECT(params, "'('");
KERF_EXPECT(module_params, "'('");
KERF_EXPECT(binding_next, "name");
KERF_EXPECT(param_next, "parameter name");
KERF_EXPECT(list_body, "']'");
KERF_EXPECT(list_rest, "']'");
KERF_EXPECT(list_tail, "']'");
KERF_EXPECT(range_end, "']'");
KERF_EXPECT(member_tok, "'x', 'y' or 'z'");
KERF_EXPECT(child, "';'");
KERF_EXPECT(stmt, "statement");
KERF_EXPECT(plain_instantiation, "module instantiation");
KERF_EXPECT(module_name_tok, "module name");
KERF_EXPECT(function_name_tok, "function name");
KERF_EXPECT(file_path, "file name");
KERF_EXPECT(path_text, "file name");
KERF_EXPECT(path_close, "'>'");

#undef KERF_EXPECT

struct errors {
    template <typename Rule>
    static constexpr const char* message = error_message<Rule>;
    // Only a failure inside must<> is an error; elsewhere it is backtracking.
    template <typename Rule>
    static constexpr bool raise_on_failure = false;
};

template <typename Rule>
struct control : pg::must_if<errors>::control<Rule> {};

}  // namespace kerf::grammar
