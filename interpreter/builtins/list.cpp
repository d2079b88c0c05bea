// List built-ins of docs/spec.md §2: len and concat, as in OpenSCAD. Results are
// bounded by the list-size limit so `concat` doubling in a recursion ends in
// a located error instead of exhausting memory.
#include "interpreter/builtins/support.hpp"
#include "interpreter/operators.hpp"

namespace kerf::builtin {
namespace {

// len of a list, a string (characters, operators.hpp) or a range (its element count; in
// OpenSCAD 2021 a range's len is undef with its warning).
Value len_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "len", 1);
    const Value& v = args[0];
    if (v.is_list()) return Value(static_cast<double>(v.as_list().size()));
    if (v.is_string()) return Value(static_cast<double>(utf8_length(v.as_string())));
    if (v.is_range() && ctx.lenient) fail(ctx, "len() parameter could not be converted");
    if (v.is_range()) return Value(static_cast<double>(v.as_range().size()));
    fail(ctx, "len: expected a list or a string, got " + describe(v));
}

// concat(a, b, ...): the elements of each list argument in order; any other
// argument (number, string, range, ...) is appended as one element.
Value concat_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    std::size_t total = 0;
    for (const Value& a : args) total += a.is_list() ? a.as_list().size() : 1;
    if (total > ctx.max_list_elements)
        throw SourceError(ctx.loc, "concat: list size limit " + std::to_string(ctx.max_list_elements) + " exceeded (" +
                      std::to_string(total) + " elements)");
    if (args.size() == 1 && args[0].is_list()) return args[0];  // shares the storage
    ValueList out;
    out.reserve(total);
    for (const Value& a : args) {
        if (a.is_list()) out.insert(out.end(), a.as_list().begin(), a.as_list().end());
        else out.push_back(a);
    }
    return Value::list(std::move(out));
}

const Entry kEntries[] = {
    {"len", "value", len_fn},
    {"concat", "...", concat_fn},
};

}  // namespace

std::span<const Entry> list_entries() { return kEntries; }

}  // namespace kerf::builtin
