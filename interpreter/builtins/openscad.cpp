// The rest of OpenSCAD 2021.01's built-in functions (docs/openscad.md
// "Built-in functions"): version, version_num, rands, lookup, search, chr,
// ord, is_function, parent_module. Their results follow OpenSCAD's implementation case by
// case (checked against `openscad -o out.echo`); a wrong call is a
// SoftError, with OpenSCAD's warning text where it has one.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "grammar/literals.hpp"
#include "interpreter/builtins/support.hpp"
#include "interpreter/openscad_ops.hpp"
#include "interpreter/operators.hpp"

namespace kerf::builtin {
namespace {

Value version_fn(std::span<const Value>, const BuiltinContext&) {
    return Value::list({Value(2021), Value(1), Value(0)});
}

// version_num() is 20210100; version_num([y, m, d]) is y*10000 + m*100 + d.
Value version_num_fn(std::span<const Value> args, const BuiltinContext&) {
    if (args.empty()) return Value(20210100);
    const Value& v = args[0];
    if (!v.is_vector() || v.as_list().size() < 2 || v.as_list().size() > 3) return Value();
    const ValueList& l = v.as_list();
    return Value(l[0].as_number() * 10000 + l[1].as_number() * 100 + (l.size() > 2 ? l[2].as_number() : 0));
}

// One stream for the run's thread, as OpenSCAD has one generator (a
// Mersenne twister drawn through uniform_real_distribution, as here): a
// seeded call reseeds it, an unseeded call goes on from where it is. It
// starts at a fixed seed, so kerf runs are reproducible (OpenSCAD seeds
// from the clock).
std::mt19937& random_stream() {
    thread_local std::mt19937 stream(20210100u);
    return stream;
}

// The seed OpenSCAD 2021 makes of a number: its numeric hash modulo the
// Mersenne prime 2^31 - 1 (the rational value |v| = m * 2^e reduced modulo
// P, where 2^31 is 1, so 2^e is 2^(e mod 31)), signed, as a 32-bit word;
// infinities are +-314159 and NaN 0. Equal seeds give OpenSCAD's sequence.
std::uint32_t openscad_seed(double v) {
    constexpr std::uint64_t P = (1ull << 31) - 1;
    if (std::isnan(v)) return 0;
    if (std::isinf(v)) return static_cast<std::uint32_t>(v > 0 ? 314159 : -314159);
    int e = 0;
    const double fraction = std::frexp(std::abs(v), &e);                 // |v| = fraction * 2^e
    const auto m = static_cast<std::uint64_t>(std::ldexp(fraction, 53));  // exact: 53 bits
    e -= 53;
    const int shift = ((e % 31) + 31) % 31;
    std::uint64_t x = m % P;
    x = (x << shift) % P;  // x < 2^31 and shift <= 30: no overflow
    const auto h = static_cast<std::int64_t>(x) * (v < 0 ? -1 : 1);
    return static_cast<std::uint32_t>(static_cast<std::int32_t>(h));
}

// rands(min, max, count [, seed]): |count| truncated numbers uniform in
// [min, max) (the bounds swapped if needed), as OpenSCAD counts them; an
// infinite or NaN bound is -DBL_MAX/2 (min) or DBL_MAX/2 (max), with
// OpenSCAD's warning.
Value rands_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    if (args.size() != 3 && args.size() != 4) fail(ctx, "rands() number of parameters does not match");
    for (const Value& a : args)
        if (!a.is_number()) fail(ctx, "rands() parameter could not be converted");
    double lo = args[0].as_number(), hi = args[1].as_number();
    constexpr double half = std::numeric_limits<double>::max() / 2;
    if (!std::isfinite(lo)) {
        if (!ctx.lenient) fail(ctx, "rands() range cannot be infinite");
        ctx.warn("rands() range min cannot be infinite: resetting to -" + format_number(half));
        lo = -half;
    }
    if (!std::isfinite(hi)) {
        if (!ctx.lenient) fail(ctx, "rands() range cannot be infinite");
        ctx.warn("rands() range max cannot be infinite: resetting to " + format_number(half));
        hi = half;
    }
    if (hi < lo) std::swap(lo, hi);
    double count = std::abs(args[2].as_number());
    if (!std::isfinite(count)) count = 1;  // OpenSCAD: "resetting number of results to 1"
    if (count >= static_cast<double>(ctx.max_list_elements) + 1)
        throw SourceError(ctx.loc, "rands: list size limit " + std::to_string(ctx.max_list_elements) + " exceeded");
    std::mt19937& stream = random_stream();
    if (args.size() == 4) stream.seed(openscad_seed(args[3].as_number()));
    std::uniform_real_distribution<double> uniform(lo, hi);
    ValueList out;
    out.reserve(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) out.push_back(Value(lo == hi ? lo : uniform(stream)));
    return Value::list(std::move(out));
}

bool vec2(const Value& v, double& x, double& y) {
    if (!v.is_vector(2)) return false;
    x = v.as_list()[0].as_number();
    y = v.as_list()[1].as_number();
    return true;
}

// lookup(key, [[k, v], ...]): linear interpolation between the nearest
// keys below and above, the end value outside; entries that are not two
// numbers are skipped; the table need not be sorted (OpenSCAD's scan).
Value lookup_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    if (args.size() != 2) fail(ctx, "lookup() number of parameters does not match");
    if (!args[0].is_number() || !std::isfinite(args[0].as_number()))
        fail(ctx, "lookup(" + to_repr(args[0]) + ", ...) first argument is not a number");
    const double p = args[0].as_number();
    if (!args[1].is_list() || args[1].as_list().empty()) return Value();
    const ValueList& table = args[1].as_list();
    double low_p, low_v, high_p, high_v;
    if (!vec2(table[0], low_p, low_v)) return Value();
    high_p = low_p;
    high_v = low_v;
    for (std::size_t i = 1; i < table.size(); ++i) {
        double tp, tv;
        if (!vec2(table[i], tp, tv)) continue;
        if (tp <= p && (tp > low_p || low_p > p)) {
            low_p = tp;
            low_v = tv;
        }
        if (tp >= p && (tp < high_p || high_p < p)) {
            high_p = tp;
            high_v = tv;
        }
    }
    if (p <= low_p) return Value(high_v);
    if (p >= high_p) return Value(low_v);
    const double f = (p - low_p) / (high_p - low_p);
    return Value(high_v * f + low_v * (1 - f));
}

// Adds the index j to a search result: `one` (the default of one match per
// term) collects indices flat, otherwise each term gets its own list.
struct Matches {
    unsigned per_term;
    ValueList flat;
    bool term(const std::function<bool(std::size_t)>& hit, std::size_t n, bool empty_when_missing) {
        ValueList mine;
        unsigned count = 0;
        for (std::size_t j = 0; j < n; ++j) {
            if (!hit(j)) continue;
            ++count;
            if (per_term == 1) {
                flat.push_back(Value(static_cast<double>(j)));
                break;
            }
            mine.push_back(Value(static_cast<double>(j)));
            if (per_term > 1 && count >= per_term) break;
        }
        if (per_term != 1 || (count == 0 && empty_when_missing)) flat.push_back(Value::list(std::move(mine)));
        return count > 0;
    }
};

const Value& column(const Value& entry, unsigned col, bool& ok) {
    static const Value none;
    ok = entry.is_list() && col < entry.as_list().size();
    return ok ? entry.as_list()[col] : none;
}

// search(what, table [, per_term = 1 [, column = 0]]) in all its forms:
// a number or a list of values matched against table entries (or their
// column), a string's characters against a string's characters or the
// first character of each entry's column.
Value search_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    if (args.size() < 2) fail(ctx, "search() number of parameters does not match");
    auto whole = [](const Value& v) -> unsigned {
        if (!v.is_number() || !(v.as_number() >= 0)) return 0;
        return v.as_number() >= 4294967295.0 ? 4294967295u : static_cast<unsigned>(v.as_number());
    };
    const Value& what = args[0];
    const Value& table = args[1];
    Matches m{args.size() > 2 ? whole(args[2]) : 1u, {}};
    const unsigned col = args.size() > 3 ? whole(args[3]) : 0u;
    static const ValueList no_entries;
    const ValueList& entries = table.is_list() ? table.as_list() : no_entries;
    // Each pair compared is charged (ctx.walk): a list of terms against a
    // long table is quadratic within one call.
    auto matches_value = [&](const Value& x, std::size_t j) {
        ctx.walk(1);
        bool ok;
        const Value& c = column(entries[j], col, ok);
        return (col == 0 && x == entries[j]) || (ok && x == c);
    };
    if (what.is_number()) {
        // One list of indices, up to per_term of them (0: all).
        unsigned count = 0;
        for (std::size_t j = 0; j < entries.size(); ++j) {
            if (!matches_value(what, j)) continue;
            m.flat.push_back(Value(static_cast<double>(j)));
            if (m.per_term != 0 && ++count >= m.per_term) break;
        }
        return Value::list(std::move(m.flat));
    }
    if (what.is_list()) {
        for (const Value& x : what.as_list())
            m.term([&](std::size_t j) { return matches_value(x, j); }, entries.size(), true);
        return Value::list(std::move(m.flat));
    }
    if (!what.is_string()) return Value();
    if (table.is_string()) {
        const std::vector<std::string_view> hay = characters(table.as_string());
        for (std::string_view c : characters(what.as_string()))
            m.term(
                [&](std::size_t j) {
                    ctx.walk(1);
                    return hay[j] == c;
                },
                hay.size(), false);
        return Value::list(std::move(m.flat));
    }
    for (std::size_t j = 0; j < entries.size(); ++j) {
        bool ok;
        column(entries[j], col, ok);
        if (!ok) return Value::list({});  // OpenSCAD: "Invalid entry in search vector"
    }
    for (std::string_view c : characters(what.as_string()))
        m.term(
            [&](std::size_t j) {
                ctx.walk(1);
                bool ok;
                const std::string entry = to_str(column(entries[j], col, ok));
                const std::vector<std::string_view> first = characters(entry);
                return !first.empty() && first[0] == c;
            },
            entries.size(), false);
    return Value::list(std::move(m.flat));
}

// chr(65, [72, 105], [67:69]): the characters of valid code points (1 to
// 0x10FFFF, no surrogates; fractions truncated), lists flattened, ranges
// taken element by element (one of 10,000 elements or more adds nothing,
// with OpenSCAD's warning); anything else adds nothing, as in OpenSCAD.
void chr_of(const Value& v, std::string& out, const BuiltinContext& ctx) {
    if (v.is_list()) {
        for (const Value& e : v.as_list()) chr_of(e, out, ctx);
        return;
    }
    if (v.is_range()) {
        const Range& r = v.as_range();
        if (const std::uint32_t n = openscad_range_count(r); n >= 10000) {
            ctx.warn("Bad range parameter in for statement: too many elements (" + std::to_string(n) + ").");
            return;
        }
        for (std::uint64_t i = 0, n = r.size(); i < n; ++i) chr_of(Value(r.at(i)), out, ctx);
        return;
    }
    if (!v.is_number()) return;
    const double d = v.as_number();
    if (!(d >= 1 && d < 0x110000)) return;
    const auto c = static_cast<std::uint32_t>(d);
    if (c >= 0xD800 && c <= 0xDFFF) return;
    grammar::append_utf8(out, c);
}

Value chr_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    std::string out;
    for (const Value& a : args) chr_of(a, out, ctx);
    return Value::string(std::move(out));
}

// ord("A") is 65: the first code point; "" is undef, and so is a string
// that is not UTF-8 (a Latin-1 byte of a .scad file), with OpenSCAD's
// warning.
Value ord_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    if (args.empty()) return Value();
    if (args.size() > 1)
        fail(ctx, "ord() called with " + std::to_string(args.size()) + " arguments, only 1 argument expected");
    if (!args[0].is_string()) fail(ctx, "ord() argument " + to_repr(args[0]) + " is not of type string");
    const std::string& s = args[0].as_string();
    if (s.empty()) return Value();
    if (!valid_utf8(s)) fail(ctx, "ord() argument '" + s + "' is not a valid utf8 string");
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    std::uint32_t c = b(0);
    std::size_t extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    if (extra) c &= 0x3F >> extra;
    for (std::size_t i = 1; i <= extra && i < s.size(); ++i) c = (c << 6) | (b(i) & 0x3F);
    return Value(static_cast<double>(c));
}

Value is_function_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "is_function", 1);
    return Value(args[0].is_function());
}

// parent_module(n): the name of the user module n calls out from the one
// running (0 is itself; no argument is 1). OpenSCAD truncates n to an int
// (a value outside int is INT_MIN, as its x86 build converts it); a
// non-number is undef without a warning.
Value parent_module_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    if (args.size() > 1) fail(ctx, "parent_module() number of parameters does not match");
    double d = 1;
    if (!args.empty()) {
        if (!args[0].is_number()) return Value();
        d = args[0].as_number();
    }
    constexpr double lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
    const long long n = d > lo - 1 && d < hi + 1.0 ? static_cast<long long>(d) : static_cast<long long>(lo);
    if (n < 0) fail(ctx, "Negative parent module index (" + std::to_string(n) + ") not allowed");
    if (static_cast<unsigned long long>(n) >= ctx.modules.size())
        fail(ctx, "Parent module index (" + std::to_string(n) + ") greater than the number of modules on the stack");
    return Value::string(std::string(ctx.modules[ctx.modules.size() - 1 - static_cast<std::size_t>(n)]));
}

const Entry kEntries[] = {
    {"version", "", version_fn},
    {"version_num", "", version_num_fn},
    {"rands", "min_value max_value value_count seed_value", rands_fn},
    {"lookup", "key table", lookup_fn},
    {"search", "match_value string_or_vector num_returns_per_match index_col_num", search_fn},
    {"chr", "...", chr_fn},
    {"ord", "string", ord_fn},
    {"is_function", "x", is_function_fn},
    {"parent_module", "n", parent_module_fn},
};

}  // namespace

std::span<const Entry> openscad_entries() { return kEntries; }

}  // namespace kerf::builtin
