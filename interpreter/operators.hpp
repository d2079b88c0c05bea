// The arithmetic, comparison and indexing operators of docs/spec.md §2 on Values.
// Strict: an operator that does not apply to its operands' types (`1 + "a"`,
// `undef * 2`, vectors of different lengths) is a located error, where
// OpenSCAD would warn and yield undef. Those errors are SoftErrors; the
// OpenSCAD dialect answers them with openscad_ops.hpp instead.
#pragma once
#include <cstdint>
#include <string_view>

#include "grammar/source.hpp"
#include "interpreter/value.hpp"

namespace kerf {

// Bounds the number of values one operation may create: nested lists share
// structure, so `[l, l] + [l, l]` can stand for exponentially many numbers;
// past `limit` the operation is the error "list size limit N exceeded".
struct OpBudget {
    std::uint64_t limit;
    std::uint64_t used = 0;
};

// op is one of "-", "+" (unary).
Value unary_op(std::string_view op, const Value& a, const SourceLoc& loc, OpBudget* budget = nullptr);

// op is one of "+ - * / % ^ < <= > >= == !=" (&& and || short-circuit in the
// evaluator).
Value binary_op(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, OpBudget* budget = nullptr);

// list[i], string[i] (one UTF-8 character), range[i]. The index must be an
// integral number inside the bounds: out of range is an error (kerf is
// strict; OpenSCAD yields undef).
Value index_value(const Value& object, const Value& index, const SourceLoc& loc);

// Number of UTF-8 characters (code points) in s, as OpenSCAD's len().
std::size_t utf8_length(std::string_view s);

}  // namespace kerf
