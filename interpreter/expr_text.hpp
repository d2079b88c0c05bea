// An expression as OpenSCAD 2021 prints it: the text `echo` and `str` show
// for a function value (`function(x) (x * 2)`), fully parenthesised
// binary operations, strings escaped, numbers as echo prints them.
#pragma once
#include <string>

#include "grammar/ast.hpp"

namespace kerf {

std::string openscad_text(const ast::Expr& e);

}  // namespace kerf
