// find_builtin: one sorted name table over the groups of builtins_*.cpp,
// built once, so a lookup is a binary search and adding a builtin means
// adding one entry to its group. Also the argument-check helpers they share.
#include <algorithm>
#include <vector>

#include "interpreter/builtins/support.hpp"

namespace kerf {
namespace builtin {

void fail(const BuiltinContext& ctx, std::string message) { throw SoftError(ctx.loc, std::move(message)); }

std::string describe(const Value& v) {
    switch (v.type()) {
        case ValueType::Undef: return "undef";
        case ValueType::Bool: return "a bool";
        case ValueType::Number: return "a number";
        case ValueType::String: return "a string";
        case ValueType::List: return "a list";
        case ValueType::Range: return "a range";
    }
    return "a value";
}

void expect_count(std::span<const Value> args, const BuiltinContext& ctx, std::string_view fn,
                  std::size_t min, std::size_t max) {
    if (args.size() >= min && args.size() <= max) return;
    std::string expected = std::to_string(min);
    if (max != min) expected += max == min + 1 ? " or " + std::to_string(max) : " to " + std::to_string(max);
    fail(ctx, std::string(fn) + ": expected " + expected + (max == 1 ? " argument" : " arguments") +
                  ", got " + std::to_string(args.size()));
}

double number_arg(std::span<const Value> args, std::size_t i, const BuiltinContext& ctx, std::string_view fn) {
    const Value& v = args[i];
    if (v.is_number()) return v.as_number();
    std::string where = args.size() > 1 ? "argument " + std::to_string(i + 1) + ": " : "";
    fail(ctx, std::string(fn) + ": " + where + "expected a number, got " + describe(v));
}

}  // namespace builtin

BuiltinFn find_builtin(std::string_view name) {
    static const std::vector<builtin::Entry> table = [] {
        std::vector<builtin::Entry> all;
        for (auto group : {builtin::math_entries(), builtin::list_entries(), builtin::string_entries(),
                           builtin::openscad_entries()})
            all.insert(all.end(), group.begin(), group.end());
        std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
        return all;
    }();
    auto it = std::lower_bound(table.begin(), table.end(), name,
                               [](const builtin::Entry& e, std::string_view n) { return e.name < n; });
    return it != table.end() && it->name == name ? it->fn : nullptr;
}

}  // namespace kerf
