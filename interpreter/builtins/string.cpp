// str() and the type tests of docs/spec.md §2. str's result is bounded: a string
// longer than the list-size limit (in bytes) is a located error, checked
// before the text is built, so `str(s, s)` doubling in a recursion or str()
// of a huge shared nested list cannot exhaust memory.
#include <cmath>

#include "interpreter/builtins/support.hpp"

namespace kerf::builtin {
namespace {

// Length of to_str(v) (quoted: to_repr form, used inside lists), stopping
// as soon as it exceeds `cap`; every element adds at least one byte, so the
// walk visits at most ~cap elements even for vast shared structures.
std::uint64_t text_length(const Value& v, bool quoted, std::uint64_t cap) {
    switch (v.type()) {
        case ValueType::Undef: return 5;
        case ValueType::Bool: return v.as_bool() ? 4 : 5;
        case ValueType::Number: return format_number(v.as_number()).size();
        case ValueType::String: {
            const std::string& s = v.as_string();
            if (!quoted) return s.size();
            return s.size() + 2;
        }
        case ValueType::List: {
            const ValueList& items = v.as_list();
            std::uint64_t n = 2 + (items.empty() ? 0 : 2 * (items.size() - 1));
            for (const Value& e : items) {
                if (n > cap) break;
                n += text_length(e, true, cap);
            }
            return n;
        }
        case ValueType::Range: {
            const Range& r = v.as_range();
            return 8 + format_number(r.start).size() + format_number(r.step).size() + format_number(r.end).size();
        }
        case ValueType::Function: return to_str(v).size();
    }
    return 0;
}

// str(a, b, ...): the concatenation of each argument's text (strings bare,
// numbers as OpenSCAD prints them, lists with quoted strings inside).
Value str_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    const std::uint64_t cap = ctx.max_list_elements;
    std::uint64_t total = 0;
    for (const Value& a : args) {
        total += text_length(a, false, cap);
        if (total > cap)
            throw SourceError(ctx.loc, "str: string length limit " + std::to_string(cap) + " exceeded");
    }
    std::string out;
    out.reserve(total);
    for (const Value& a : args) out += to_str(a);
    return Value::string(std::move(out));
}

template <bool (*Test)(const Value&)>
Value type_test(std::span<const Value> args, const BuiltinContext& ctx, std::string_view name) {
    expect_count(args, ctx, name, 1);
    return Value(Test(args[0]));
}

bool undef_test(const Value& v) { return v.is_undef(); }
// NaN is not a number here, as in OpenSCAD (is_num(0/0) is false).
bool num_test(const Value& v) { return v.is_number() && !std::isnan(v.as_number()); }
bool bool_test(const Value& v) { return v.is_bool(); }
bool string_test(const Value& v) { return v.is_string(); }
bool list_test(const Value& v) { return v.is_list(); }  // a range is not a list (OpenSCAD)

#define KERF_TYPE_TEST(name, f) \
    Entry { #name, "x", [](std::span<const Value> a, const BuiltinContext& c) { return type_test<f>(a, c, #name); } }

const Entry kEntries[] = {
    {"str", "...", str_fn},
    KERF_TYPE_TEST(is_undef, undef_test),
    KERF_TYPE_TEST(is_num, num_test),
    KERF_TYPE_TEST(is_bool, bool_test),
    KERF_TYPE_TEST(is_string, string_test),
    KERF_TYPE_TEST(is_list, list_test),
};

}  // namespace

std::span<const Entry> string_entries() { return kEntries; }

}  // namespace kerf::builtin
