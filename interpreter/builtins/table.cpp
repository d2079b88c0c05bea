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
        case ValueType::Function: return "a function";
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

namespace {
const std::vector<builtin::Entry>& builtin_table() {
    static const std::vector<builtin::Entry> table = [] {
        std::vector<builtin::Entry> all;
        for (auto group : {builtin::math_entries(), builtin::list_entries(), builtin::string_entries(),
                           builtin::openscad_entries()})
            all.insert(all.end(), group.begin(), group.end());
        std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
        return all;
    }();
    return table;
}
}  // namespace

std::vector<std::string_view> builtin_names() {
    std::vector<std::string_view> out;
    for (const builtin::Entry& e : builtin_table()) out.push_back(e.name);
    return out;
}

const Builtin* find_builtin(std::string_view name) {
    const auto& table = builtin_table();
    auto it = std::lower_bound(table.begin(), table.end(), name,
                               [](const builtin::Entry& e, std::string_view n) { return e.name < n; });
    return it != table.end() && it->name == name ? &*it : nullptr;
}

std::string_view builtin_param(const Builtin& b, std::size_t i, std::size_t count) {
    // The alternative written for `count` arguments, else the last (longest).
    std::string_view list = b.params;
    for (std::string_view rest = b.params; !rest.empty();) {
        std::size_t bar = rest.find(" | ");
        std::string_view alt = rest.substr(0, bar);
        list = alt;
        if (static_cast<std::size_t>(std::count(alt.begin(), alt.end(), ' ')) + !alt.empty() == count) break;
        rest = bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 3);
    }
    for (std::size_t k = 0; !list.empty(); ++k) {
        std::size_t sp = list.find(' ');
        std::string_view word = list.substr(0, sp);
        if (word == "...") return {};
        if (k == i) return word;
        list = sp == std::string_view::npos ? std::string_view() : list.substr(sp + 1);
    }
    return {};
}

}  // namespace kerf
