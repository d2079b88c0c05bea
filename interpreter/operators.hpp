// The arithmetic, comparison and indexing operators of spec §2 on Values.
// Strict: an operator that does not apply to its operands' types (`1 + "a"`,
// `undef * 2`, vectors of different lengths) is a located error, where
// OpenSCAD would warn and yield undef.
#pragma once
#include <string_view>

#include "grammar/source.hpp"
#include "interpreter/value.hpp"

namespace kerf {

// op is one of "-", "+" (unary).
Value unary_op(std::string_view op, const Value& a, const SourceLoc& loc);

// op is one of "+ - * / % ^ < <= > >= == !=" (&& and || short-circuit in the
// evaluator). A list result is never longer than its list operands.
Value binary_op(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc);

// list[i], string[i] (one UTF-8 character), range[i]. The index must be an
// integral number inside the bounds: out of range is an error (kerf is
// strict; OpenSCAD yields undef).
Value index_value(const Value& object, const Value& index, const SourceLoc& loc);

// Number of UTF-8 characters (code points) in s, as OpenSCAD's len().
std::size_t utf8_length(std::string_view s);

}  // namespace kerf
