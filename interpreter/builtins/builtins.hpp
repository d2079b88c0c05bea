// Built-in functions of docs/spec.md §2 (sin cos ... str is_*): the evaluator looks
// a callee up here when no user function of that name is in scope. Each
// builtin receives its already-evaluated positional arguments (named
// arguments to a builtin are rejected by the evaluator) and reports user
// errors as kerf::SourceError at ctx.loc, e.g. "sqrt: expected a number,
// got string".
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "grammar/source.hpp"
#include "interpreter/value.hpp"

namespace kerf {

struct BuiltinContext {
    const SourceLoc& loc;                 // the call expression
    std::uint64_t max_list_elements;      // EvalLimits::list_elements: a result
                                          // list longer than this is an error
                                          // "list size limit N exceeded"
};

using BuiltinFn = Value (*)(std::span<const Value> args, const BuiltinContext& ctx);

// The builtin called `name`, or null when there is none.
BuiltinFn find_builtin(std::string_view name);

}  // namespace kerf
