// The values of the language (docs/spec.md §2): undef, bool, number, string, list,
// range, function (a function literal with what it captured, scope.hpp). Copying a Value is cheap: strings and lists are shared, immutable
// arrays (bindings are immutable, so sharing is safe), ranges stay lazy
// (three doubles) so `[0:1e12]` costs nothing until someone iterates it.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
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
    Value() = default;  // undef
    Value(double n) : v_(n) {}
    Value(int n) : v_(static_cast<double>(n)) {}
    Value(bool b) : v_(b) {}
    Value(const char*) = delete;  // would silently become bool: use Value::string

    static Value undef() { return Value(); }
    static Value number(double n) { return Value(n); }
    static Value boolean(bool b) { return Value(b); }
    static Value string(std::string s);
    static Value list(ValueList items);
    static Value list_shared(std::shared_ptr<const ValueList> items);
    static Value range(double start, double step, double end) { return Value(Range{start, step, end}); }
    static Value range(const Range& r) { return Value(r); }
    static Value function(ClosurePtr f);

    ValueType type() const { return static_cast<ValueType>(v_.index()); }
    const char* type_name() const { return kerf::type_name(type()); }
    bool is_undef() const { return type() == ValueType::Undef; }
    bool is_bool() const { return type() == ValueType::Bool; }
    bool is_number() const { return type() == ValueType::Number; }
    bool is_string() const { return type() == ValueType::String; }
    bool is_list() const { return type() == ValueType::List; }
    bool is_range() const { return type() == ValueType::Range; }
    bool is_function() const { return type() == ValueType::Function; }

    // Accessors: precondition is the matching is_*() (checked by std::get).
    double as_number() const { return std::get<double>(v_); }
    bool as_bool() const { return std::get<bool>(v_); }
    const std::string& as_string() const { return *std::get<StrPtr>(v_); }
    const ValueList& as_list() const { return *std::get<ListPtr>(v_); }
    const std::shared_ptr<const ValueList>& list_ptr() const { return std::get<ListPtr>(v_); }
    const Range& as_range() const { return std::get<Range>(v_); }
    const eval::Closure& as_function() const { return *std::get<ClosurePtr>(v_); }

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
    explicit Value(Range r) : v_(r) {}
    // Order matches ValueType.
    std::variant<std::monostate, bool, double, StrPtr, ListPtr, Range, ClosurePtr> v_;
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
