// Test helper: call a built-in directly through find_builtin (no parser or
// evaluator involved), with a small list limit to exercise the bounds.
#pragma once
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "interpreter/builtins/builtins.hpp"

namespace kerf::test {

inline Value call_builtin(const std::string& name, std::vector<Value> args, std::uint64_t max_list = 1000) {
    const Builtin* b = find_builtin(name);
    if (!b) throw std::logic_error("no builtin " + name);
    SourceLoc loc;
    loc.line = 7;
    loc.col = 3;
    BuiltinContext ctx{loc, max_list};
    return b->fn(args, ctx);
}

inline Value str_v(const char* s) { return Value::string(s); }
inline Value list_v(std::initializer_list<double> xs) {
    ValueList out;
    for (double x : xs) out.emplace_back(x);
    return Value::list(std::move(out));
}

}  // namespace kerf::test
