// Expression rules of .sdl (docs/spec.md §2). Precedence, lowest to highest:
//   ?:   ||   &&   == !=   < <= > >=   + -   * / %   unary - + !   ^ (right)
//   postfix [i] .x .y .z   primary (literal, name, call, (e), [list|range],
//   let(...) e, echo(...) e, assert(...) e)
// Binary levels are iterative (`operand (op operand)*`) and reduced left to
// right by the actions, so only genuinely nested constructs recurse, and
// each recursion goes through a nest<> (rules_nest.hpp).
//
// Actions fire only after a commit point (if_must / nest after its head, or
// a lookahead at<> that guarantees the rest matches), so nothing is ever
// built for input that is later backtracked over.
#pragma once
#include "grammar/rules_lexical.hpp"
#include "grammar/rules_nest.hpp"

namespace kerf::grammar {

struct expr;
struct list_element;

// ---- argument and binding lists ------------------------------------------
// `(a, b = 2,)`: call arguments, positional or named, trailing comma allowed.
struct args_open : lparen {};                    // starts a binding list
struct arg_name : name {};                       // `b` of `b = 2`
struct named_arg : pg::if_must<pg::seq<pg::at<name, ws, assign_eq>, arg_name, ws, assign_eq>, expr> {};
struct positional_arg : pg::seq<expr> {};
struct arg : pg::sor<named_arg, positional_arg> {};
// OpenSCAD skips an empty argument or list element (`f(1,,2)`, `[8,,"E"]`).
struct empty_item : pg::seq<openscad_on, pg::at<pg::one<','>>> {};
struct arg_next : pg::sor<pg::at<rparen>, arg, empty_item> {};
// The first argument may be empty too (`max(, 3)`, `cube(, center = true)`).
struct arg_first : pg::sor<arg, empty_item> {};
struct call_args : nest<args_open, pg::opt<arg_first, pg::star<pg::if_must<comma, arg_next>>>, pg::must<rparen>> {};

// `(i = r, j = s)`: bindings that must be named (for, let).
struct binding_name : name {};
struct binding : pg::if_must<pg::seq<binding_name, ws>, assign_eq, expr> {};
struct binding_next : pg::sor<pg::at<rparen>, binding> {};
struct bind_list
    : nest<args_open, pg::must<binding_next>, pg::star<pg::if_must<comma, binding_next>>, pg::must<rparen>> {};

// `(a, b = 2)`: parameters of a function or module definition or literal.
struct param_name : name {};
struct param_default : pg::if_must<assign_eq, expr> {};
struct param : pg::seq<param_name, ws, pg::opt<param_default>> {};
struct param_next : pg::sor<pg::at<rparen>, param> {};
struct params : nest<args_open, pg::must<param_next>, pg::star<pg::if_must<comma, param_next>>, pg::must<rparen>> {};

// ---- primaries ------------------------------------------------------------
struct number_tok : pg::seq<number_lit, ws> {};
struct string_tok : pg::seq<string_lit, ws> {};
struct true_lit : pg::keyword<'t', 'r', 'u', 'e'> {};
struct false_lit : pg::keyword<'f', 'a', 'l', 's', 'e'> {};
struct undef_lit : pg::keyword<'u', 'n', 'd', 'e', 'f'> {};
struct literal_tok : pg::seq<pg::at<pg::one<'t', 'f', 'u'>>, pg::sor<true_lit, false_lit, undef_lit>, ws> {};

struct paren_expr : nest<lparen, pg::must<expr>, pg::must<rparen>> {};

// Lists and ranges share the opening `[`: the first element decides.
struct list_open : lbracket {};  // marks where the items start
struct list_empty : rbracket {};
struct list_next : pg::sor<pg::at<rbracket>, list_element, empty_item> {};
struct list_tail : pg::seq<pg::star<pg::if_must<comma, list_next>>, pg::must<rbracket>> {};
struct range_end : pg::sor<rbracket, pg::if_must<colon, expr, rbracket>> {};
struct range_tail : pg::if_must<colon, expr, range_end> {};
struct list_rest : pg::sor<range_tail, list_tail> {};
struct generator_elem;
struct list_body
    : pg::sor<list_empty, pg::if_must<generator_elem, list_tail>, pg::if_must<expr, list_rest>,
              pg::seq<empty_item, list_tail>> {};
struct list_expr : nest<list_open, pg::must<list_body>> {};

// Generators (list comprehension elements), only inside `[...]`.
struct gen_for_kw : kw<'f', 'o', 'r'> {};
// `for (init; cond; incr)`, OpenSCAD's C-style loop: after the first
// binding list comes `;` instead of `)`; `cfor_tail` marks the loop as one.
struct cfor_semi : pg::seq<pg::one<';'>, ws> {};
struct cfor_cond : pg::seq<expr> {};
struct cfor_incr_open : pg::success {};  // the increment's binding list starts here
struct cfor_incr : pg::seq<cfor_incr_open, pg::must<binding_next>, pg::star<pg::if_must<comma, binding_next>>> {};
struct cfor_tail : pg::if_must<cfor_semi, cfor_cond, cfor_semi, cfor_incr, rparen> {};
struct for_header_end : pg::sor<rparen, cfor_tail> {};
struct for_bindings : nest<args_open, pg::must<binding_next>, pg::star<pg::if_must<comma, binding_next>>,
                           pg::must<for_header_end>> {};
struct gen_for : nest<gen_for_kw, pg::must<for_bindings>, pg::must<list_element>> {};
struct gen_if_kw : kw<'i', 'f'> {};  // marks where the items start
struct gen_else : pg::if_must<kw<'e', 'l', 's', 'e'>, list_element> {};
struct gen_if
    : nest<gen_if_kw, pg::must<lparen>, pg::must<expr>, pg::must<rparen>, pg::must<list_element>, pg::opt<gen_else>> {};
struct gen_let : nest<kw<'l', 'e', 't'>, pg::must<bind_list>, pg::must<list_element>> {};
struct gen_each : nest<kw<'e', 'a', 'c', 'h'>, pg::must<list_element>> {};
struct generator : pg::sor<gen_for, gen_if, gen_let, gen_each> {};
// `( if (c) x )`: a generator in parentheses, as OpenSCAD allows. Only a
// generator no expression starts like (for, if, each): `(let (a = 1) a)`
// stays the let expression, which may go on (`(let (a = 1) a) + 1`).
struct gen_paren_head : pg::seq<lparen, pg::at<pg::sor<gen_for_kw, gen_if_kw, kw<'e', 'a', 'c', 'h'>>>> {};
struct gen_paren : nest<gen_paren_head, pg::must<generator>, pg::must<rparen>> {};
struct generator_elem : pg::sor<generator, gen_paren> {};
struct list_element : pg::sor<generator_elem, expr> {};

// Expression prefixes `let (...) e`, `echo (...) e`, `assert (...) e`.
struct let_expr : nest<kw<'l', 'e', 't'>, pg::must<bind_list>, pg::must<expr>> {};
struct echo_head : pg::seq<pg::keyword<'e', 'c', 'h', 'o'>, ws, pg::at<pg::one<'('>>> {};
// OpenSCAD lets the expression after `echo(...)`/`assert(...)` be empty
// (`x = echo("hi");` is undef); kerf's own dialect requires it.
struct empty_body : pg::seq<openscad_on, pg::success> {};
struct prefix_body : pg::sor<expr, empty_body> {};
struct echo_expr : nest<echo_head, pg::must<call_args>, pg::must<prefix_body>> {};
struct assert_head : pg::seq<pg::keyword<'a', 's', 's', 'e', 'r', 't'>, ws, pg::at<pg::one<'('>>> {};
struct assert_expr : nest<assert_head, pg::must<call_args>, pg::must<prefix_body>> {};

// A function literal `function (x) x * 2` (a value, docs/language.md §6).
struct function_lit_head
    : pg::seq<pg::keyword<'f', 'u', 'n', 'c', 't', 'i', 'o', 'n'>, ws, pg::at<pg::one<'('>>> {};
struct function_lit : nest<function_lit_head, pg::must<params>, pg::must<expr>> {};

struct callee : name {};
struct call_expr : pg::if_must<pg::seq<pg::at<name, ws, pg::one<'('>>, callee, ws>, call_args> {};
struct ident_name : name {};
struct ident_expr : pg::seq<ident_name, ws> {};

// Everything that starts with a letter is tried only after a one-byte test.
struct word_primary : pg::sor<literal_tok, let_expr, echo_expr, assert_expr, function_lit, call_expr, ident_expr> {};
struct primary : pg::sor<pg::seq<pg::at<pg::digit>, pg::at<name>, word_primary>,  // `608_dia` (OpenSCAD)
                         number_tok, string_tok, paren_expr, list_expr,
                         pg::seq<pg::at<pg::ranges<'a', 'z', 'A', 'Z', '_', '_', '$', '$'>>, word_primary>> {};

// ---- postfix and operators -------------------------------------------------
struct index_op : nest<lbracket, pg::must<expr>, pg::must<rbracket>> {};
// `.x`, `.y`, `.z`; OpenSCAD's dialect takes any name there (`v.w` is undef).
struct member_name : pg::sor<pg::seq<pg::one<'x', 'y', 'z'>, pg::not_at<pg::identifier_other>>,
                             pg::seq<openscad_on, pg::identifier>> {};
struct member_tok : pg::seq<member_name, ws> {};
struct member_op : pg::if_must<pg::seq<pg::one<'.'>, ws>, member_tok> {};
// A call of whatever value an expression has: `f(1)(2)`, `fs[0](3)`.
struct call_op : pg::seq<pg::at<pg::one<'('>>, call_args> {};
struct postfix : pg::seq<primary, pg::star<pg::sor<index_op, member_op, call_op>>> {};

struct unary;
struct unary_op : pg::one<'-', '+', '!'> {};
struct unary_prefixed : nest<pg::seq<unary_op, ws>, pg::must<unary>> {};
struct pow_op : pg::one<'^'> {};
struct power_tail : nest<pg::seq<pow_op, ws>, pg::must<unary>> {};
struct power : pg::seq<postfix, pg::opt<power_tail>> {};
struct unary : pg::sor<unary_prefixed, power> {};

struct mul_op : pg::one<'*', '/', '%'> {};
struct mul_tail : pg::if_must<pg::seq<mul_op, ws>, unary> {};
struct mul_expr : pg::seq<unary, pg::star<mul_tail>> {};

struct add_op : pg::one<'+', '-'> {};
struct add_tail : pg::if_must<pg::seq<add_op, ws>, mul_expr> {};
struct add_expr : pg::seq<mul_expr, pg::star<add_tail>> {};

struct rel_op : pg::sor<pg::string<'<', '='>, pg::string<'>', '='>, pg::one<'<', '>'>> {};
struct rel_tail : pg::if_must<pg::seq<rel_op, ws>, add_expr> {};
struct rel_expr : pg::seq<add_expr, pg::star<rel_tail>> {};

struct eq_op : pg::sor<pg::string<'=', '='>, pg::string<'!', '='>> {};
struct eq_tail : pg::if_must<pg::seq<eq_op, ws>, rel_expr> {};
struct eq_expr : pg::seq<rel_expr, pg::star<eq_tail>> {};

struct and_op : pg::string<'&', '&'> {};
struct and_tail : pg::if_must<pg::seq<and_op, ws>, eq_expr> {};
struct and_expr : pg::seq<eq_expr, pg::star<and_tail>> {};

struct or_op : pg::string<'|', '|'> {};
struct or_tail : pg::if_must<pg::seq<or_op, ws>, and_expr> {};
struct or_expr : pg::seq<and_expr, pg::star<or_tail>> {};

struct ternary_tail : nest<pg::seq<pg::one<'?'>, ws>, pg::must<expr>, pg::must<colon>, pg::must<expr>> {};
struct expr : pg::seq<or_expr, pg::opt<ternary_tail>> {};

}  // namespace kerf::grammar
