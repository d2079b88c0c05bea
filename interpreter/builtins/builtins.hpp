// Built-in functions of docs/spec.md §2 (sin cos ... str is_*): the evaluator looks
// a callee up here when no user function of that name is in scope. Each
// builtin is declared once, with its parameter names, and receives its
// already-evaluated arguments in call order (OpenSCAD takes a built-in's
// arguments in order, whatever their names: the names only document the
// call, and the evaluator checks them against the parameter list). Errors
// are kerf::SourceError at ctx.loc, e.g. "sqrt: expected a number, got
// string".
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/source.hpp"
#include "interpreter/operators.hpp"  // WorkCapReached
#include "interpreter/value.hpp"

namespace kerf {

struct WorkTally {
    std::uint64_t walked = 0;
    std::uint64_t cap = UINT64_MAX;
};

struct BuiltinContext {
    const SourceLoc& loc;                 // the call expression
    std::uint64_t max_list_elements;      // EvalLimits::list_elements: a result
                                          // list longer than this is an error
                                          // "list size limit N exceeded"
    std::span<const std::string_view> modules = {};  // user module calls,
                                          // outermost first (parent_module)
    bool lenient = false;                 // the OpenSCAD dialect (where a
                                          // builtin's result differs)
    // What a call that succeeds has to say (OpenSCAD's warning beside a
    // value); the evaluator reports each at loc.
    std::vector<std::string>* warnings = nullptr;
    void warn(std::string message) const {
        if (warnings) warnings->push_back(std::move(message));
    }
    // Values a call reads beyond its arguments' top level (search's pairs
    // compared), charged to the step limit as the arguments are; past cap
    // (what the steps left allow) walk throws WorkCapReached, so a call
    // quadratic in itself stops at the limit too.
    WorkTally* work = nullptr;
    void walk(std::uint64_t n) const {
        if (work && (work->walked += n) > work->cap) throw WorkCapReached{};
    }
};

using BuiltinFn = Value (*)(std::span<const Value> args, const BuiltinContext& ctx);

struct Builtin {
    std::string_view name;
    // The parameter names in call order, separated by spaces, as OpenSCAD's
    // manual names them ("base exponent"); "..." for any number of unnamed
    // arguments; alternatives for different argument counts separated by
    // " | " ("x | base x").
    std::string_view params;
    BuiltinFn fn;
};

// The builtin called `name`, or null when there is none.
const Builtin* find_builtin(std::string_view name);
// Every built-in function's name (for "did you mean").
std::vector<std::string_view> builtin_names();

// The name of parameter `i` of `b` when called with `count` arguments, or
// empty when that position has no name (variadic, or too many arguments).
std::string_view builtin_param(const Builtin& b, std::size_t i, std::size_t count);

}  // namespace kerf
