// The values of the language (docs/spec.md §2): undef, bool, number, string, list,
// range, function (a function literal with what it captured, scope.hpp). Copying a Value is cheap: strings and lists are shared, immutable
// arrays (bindings are immutable, so sharing is safe), ranges stay lazy
// (three doubles) so `[0:1e12]` costs nothing until someone iterates it.
#pragma once
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>  // std::bad_variant_access
#include <vector>

#include "grammar/source.hpp"

namespace kerf {

namespace eval {
struct Closure;
}
using ClosurePtr = std::shared_ptr<const eval::Closure>;

// An error that OpenSCAD's rules turn into undef and a warning with the
// same message (docs/openscad.md): a built-in function given the wrong
// types, an operator that does not apply to its operands. Strict runs
// report it as any other error; limits are never SoftErrors.
class SoftError : public SourceError {
public:
    using SourceError::SourceError;
};

class Value;
using ValueList = std::vector<Value>;

// [start : step : end], end inclusive as in OpenSCAD. Never materialised:
// size() counts the elements, at(i) computes one.
struct Range {
    double start = 0;
    double step = 1;
    double end = 0;

    // Number of elements (0 for an empty range: the step points away from
    // end). A tiny relative tolerance makes `[0:0.1:0.3]` have 4 elements as
    // users expect. Saturates at UINT64_MAX/2 for huge ranges; callers
    // compare it against their limits before iterating.
    std::uint64_t size() const;
    double at(std::uint64_t i) const { return i == 0 ? start : start + static_cast<double>(i) * step; }  // 0 * inf is NaN
    bool operator==(const Range&) const = default;
};

enum class ValueType : std::uint8_t { Undef, Bool, Number, String, List, Range, Function };

// "undef", "bool", "number", "string", "list", "range", "function" (for error messages).
const char* type_name(ValueType t);

class Value {
public:
    Value() noexcept : tag_(ValueType::Undef) {}  // undef
    Value(double n) noexcept : tag_(ValueType::Number) { u_.number = n; }
    Value(int n) noexcept : tag_(ValueType::Number) { u_.number = static_cast<double>(n); }
    Value(bool b) noexcept : tag_(ValueType::Bool) { u_.boolean = b; }
    Value(const char*) = delete;  // would silently become bool: use Value::string

    // A tagged union rather than std::variant: copying, moving and
    // destroying a number (most values a loop makes) is a tag test and a
    // few stores, inline, where the variant visited a table of functions
    // for each (docs/performance.md, "The interpreter's per-call costs").
    // Moved from, a string, list or function is undef; a bool, number or
    // range keeps its value (a copy).
    [[gnu::always_inline]] Value(const Value& o) : tag_(o.tag_) {
        if (o.shared()) copy_shared(o);
        else copy_plain(o);
    }
    [[gnu::always_inline]] Value(Value&& o) noexcept : tag_(o.tag_) {
        if (!o.shared()) {
            copy_plain(o);
            return;
        }
        switch (tag_) {
            case ValueType::String: new (&u_.str) StrPtr(std::move(o.u_.str)); break;
            case ValueType::List: new (&u_.list) ListPtr(std::move(o.u_.list)); break;
            default: new (&u_.fn) ClosurePtr(std::move(o.u_.fn)); break;
        }
        o.tag_ = ValueType::Undef;  // moved from: undef (its pointer is null: nothing to release)
    }
    Value& operator=(const Value& o) {
        if (this != &o) {
            Value copy(o);
            *this = std::move(copy);
        }
        return *this;
    }
    Value& operator=(Value&& o) noexcept {
        if (this != &o) {
            reset();
            new (this) Value(std::move(o));
        }
        return *this;
    }
    [[gnu::always_inline]] ~Value() { reset(); }

    static Value undef() { return Value(); }
    static Value number(double n) { return Value(n); }
    static Value boolean(bool b) { return Value(b); }
    static Value string(std::string s);
    static Value list(ValueList items);
    static Value list_shared(std::shared_ptr<const ValueList> items);
    static Value range(double start, double step, double end) { return Value(Range{start, step, end}); }
    static Value range(const Range& r) { return Value(r); }
    static Value function(ClosurePtr f);

    ValueType type() const { return tag_; }
    const char* type_name() const { return kerf::type_name(type()); }
    bool is_undef() const { return type() == ValueType::Undef; }
    bool is_bool() const { return type() == ValueType::Bool; }
    bool is_number() const { return type() == ValueType::Number; }
    bool is_string() const { return type() == ValueType::String; }
    bool is_list() const { return type() == ValueType::List; }
    bool is_range() const { return type() == ValueType::Range; }
    bool is_function() const { return type() == ValueType::Function; }

    // Accessors: precondition is the matching is_*(); a mismatch throws
    // std::bad_variant_access, as std::get did.
    double as_number() const { return expect(ValueType::Number), u_.number; }
    bool as_bool() const { return expect(ValueType::Bool), u_.boolean; }
    const std::string& as_string() const { return expect(ValueType::String), *u_.str; }
    const ValueList& as_list() const { return expect(ValueType::List), *u_.list; }
    const std::shared_ptr<const ValueList>& list_ptr() const { return expect(ValueType::List), u_.list; }
    const Range& as_range() const { return expect(ValueType::Range), u_.range; }
    const eval::Closure& as_function() const { return expect(ValueType::Function), *u_.fn; }

    // docs/spec.md §2: false, 0, "", [], undef are false; everything else is true
    // (any range, and NaN, as in OpenSCAD where a number is true if != 0).
    bool truthy() const;

    // Structural equality as OpenSCAD's `==`: same type and same contents;
    // numbers compare as doubles (NaN != NaN); a bool never equals a number;
    // a function equals only itself.
    bool operator==(const Value& o) const;
    bool operator!=(const Value& o) const { return !(*this == o); }

    // True for a list whose elements are all numbers (spec: a vector).
    bool is_vector() const;
    // A list of exactly n numbers.
    bool is_vector(std::size_t n) const;

private:
    using StrPtr = std::shared_ptr<const std::string>;
    using ListPtr = std::shared_ptr<const ValueList>;
    explicit Value(Range r) noexcept : tag_(ValueType::Range) { u_.range = r; }
    bool shared() const {  // string, list or function: one test of a bit mask
        constexpr unsigned kShared = 1u << unsigned(ValueType::String) | 1u << unsigned(ValueType::List) |
                                     1u << unsigned(ValueType::Function);
        return (kShared >> unsigned(tag_)) & 1u;
    }
    void copy_shared(const Value& o);  // value.cpp: o holds a string, list or function
    // Bool, number and range (undef: whatever bytes): trivially copyable, so as bytes.
    static_assert(std::is_trivially_copyable_v<Range> && sizeof(Range) >= sizeof(double),
                  "copy_plain copies a Range's bytes: the widest plain member");
    void copy_plain(const Value& o) noexcept { std::memcpy(static_cast<void*>(&u_), static_cast<const void*>(&o.u_), sizeof(Range)); }
    void release() noexcept;           // value.cpp: this holds one
    [[gnu::always_inline]] void reset() noexcept {  // GCC kept it out of line, a call per value destroyed
        if (shared()) release();
        tag_ = ValueType::Undef;
    }
    void expect(ValueType t) const {
        if (tag_ != t) [[unlikely]] bad_access();
    }
    [[noreturn]] static void bad_access();
    union Storage {
        Storage() noexcept {}
        ~Storage() {}
        bool boolean;
        double number;
        Range range;
        StrPtr str;
        ListPtr list;
        ClosurePtr fn;
    } u_;
    ValueType tag_;
};

// OpenSCAD 2021's number text, byte for byte: 6 significant digits
// (`0.333333`, `1e+6`, `100000`, `0.00001`, `1e-7`, `-0.5`), `0` for -0,
// `inf`, `-inf`, `nan`.
std::string format_number(double n);

// The text `str(v)` produces: strings as-is at the top level; inside lists
// strings are quoted (`["a", 1]`); `undef`, `true`; ranges `[0 : 1 : 5]`;
// a function as OpenSCAD prints its literal (`function(x) (x * 2)`).
std::string to_str(const Value& v);

// The text `echo(v)` shows: like to_str, but a top-level string is quoted
// too. Quotes are not escaped, as OpenSCAD prints them: `"q"uote"`.
std::string to_repr(const Value& v);

// The same, but giving up (nullopt) as soon as the text would pass
// max_chars: lists share structure, so a small value can stand for an
// exponentially long text.
std::optional<std::string> to_str_bounded(const Value& v, std::size_t max_chars);
std::optional<std::string> to_repr_bounded(const Value& v, std::size_t max_chars);

}  // namespace kerf
