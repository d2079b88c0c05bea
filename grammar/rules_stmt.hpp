// Statement rules of .sdl (docs/spec.md §3) and the whole-file grammar.
//
// A statement that can own children (instantiation, if, module body) takes a
// `child`: `;`, a `{ ... }` block whose statements become its children
// directly, or one more instantiation/if. Each child counts one nesting
// level (a child block too, once); bare blocks count one at their `{`;
// argument lists count one at their `(` like any parenthesis.
#pragma once
#include "grammar/rules_expr.hpp"

namespace kerf::grammar {

struct stmt;
struct child;

// `{ stmt* }` body shared by bare blocks and child blocks.
struct block_items : pg::star<pg::not_at<rbrace>, pg::not_at<pg::eof>, pg::must<stmt>> {};

struct empty_stmt : pg::seq<pg::one<';'>, ws> {};
struct block_open : lbrace {};
struct block_stmt : nest<block_open, block_items, pg::must<rbrace>> {};

// ---- instantiations ---------------------------------------------------------
struct modifier : pg::seq<pg::one<'!', '#', '%', '*'>, ws> {};
struct inst_name : name {};
struct stmt_args : call_args {};
struct inst_stmt : pg::if_must<pg::seq<inst_name, ws>, stmt_args, child> {};

// `for (i = r, j = s) child` and `let (a = 1) child` are instantiations of
// `for` / `let` whose arguments must be named.
struct for_kw : kw<'f', 'o', 'r'> {};
struct let_kw : kw<'l', 'e', 't'> {};
struct stmt_bindings : bind_list {};
struct for_stmt : pg::if_must<for_kw, stmt_bindings, child> {};
struct let_stmt : pg::if_must<let_kw, stmt_bindings, child> {};

// `if (c) child [else child]`
struct if_kw : kw<'i', 'f'> {};
struct if_cond : expr {};
struct else_kw : kw<'e', 'l', 's', 'e'> {};
struct else_part : pg::if_must<else_kw, child> {};
struct if_stmt : pg::seq<pg::if_must<if_kw, lparen, if_cond, rparen, child>, pg::opt<else_part>> {};

struct plain_instantiation : pg::sor<if_stmt, for_stmt, let_stmt, inst_stmt> {};
struct modified_stmt : pg::if_must<pg::plus<modifier>, plain_instantiation> {};
struct instantiation : pg::sor<modified_stmt, plain_instantiation> {};

struct child_empty : pg::seq<pg::one<';'>, ws> {};
// Not a nest<>: the `child` around it already counts this level.
struct child_block : pg::seq<lbrace, block_items, pg::must<rbrace>> {};
struct child_stmt : pg::sor<child_empty, child_block, instantiation> {};
struct child : counted<child_stmt> {};

// ---- definitions and bindings -----------------------------------------------

struct module_kw : kw<'m', 'o', 'd', 'u', 'l', 'e'> {};
struct module_name : name {};
struct module_name_tok : pg::seq<module_name, ws> {};
struct module_params : params {};
struct module_def : pg::if_must<module_kw, module_name_tok, module_params, child> {};

struct function_kw : kw<'f', 'u', 'n', 'c', 't', 'i', 'o', 'n'> {};
struct function_name : name {};
struct function_name_tok : pg::seq<function_name, ws> {};
struct function_def : pg::if_must<function_kw, function_name_tok, params, assign_eq, expr, semi> {};

struct assign_name : name {};
struct assign_stmt : pg::if_must<pg::seq<pg::at<name, ws, assign_eq>, assign_name, ws>, assign_eq, expr, semi> {};

// `include <path>` / `include "path"` (and `use`): the path is kept as
// written (`<...>` raw, a string decoded); no `;` is needed, as in OpenSCAD.
struct path_text : pg::plus<pg::not_one<'>', '\n', '\r'>> {};
struct path_close : pg::one<'>'> {};
struct angle_path : pg::if_must<pg::one<'<'>, path_text, path_close> {};
struct quoted_path : string_lit {};
// `use <>`: OpenSCAD's dialect takes it (and warns that it cannot open '').
struct empty_path : pg::seq<openscad_on, pg::string<'<', '>'>> {};
struct file_path : pg::seq<pg::sor<empty_path, angle_path, quoted_path>, ws> {};
struct include_stmt : pg::if_must<kw<'i', 'n', 'c', 'l', 'u', 'd', 'e'>, file_path> {};
struct use_stmt : pg::if_must<kw<'u', 's', 'e'>, file_path> {};

struct stmt : pg::sor<empty_stmt, block_stmt, module_def, function_def, include_stmt, use_stmt, assign_stmt,
                      instantiation> {};

struct program : pg::seq<ws, pg::star<pg::not_at<pg::eof>, pg::must<stmt>>> {};

}  // namespace kerf::grammar
