#include "interpreter/value.hpp"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <algorithm>
#include <limits>

#include "interpreter/expr_text.hpp"
#include "interpreter/scope.hpp"

namespace kerf {

std::uint64_t Range::size() const {
    constexpr double cap = 4.0e18;
    // A field that is not finite (only the OpenSCAD dialect makes one), as
    // OpenSCAD 2021.01 counts it: a NaN anywhere or a step pointing away
    // from the end is empty; a begin equal to the end, or an infinite step,
    // the begin alone; otherwise (an infinite bound) endless.
    if (!std::isfinite(start) || !std::isfinite(step) || !std::isfinite(end)) {
        if (std::isnan(start) || std::isnan(step) || std::isnan(end)) return 0;
        if (step < 0 ? start < end : start > end) return 0;
        if (start == end || std::isinf(step)) return 1;
        return static_cast<std::uint64_t>(cap);
    }
    if (step == 0) return 0;
    double span = end - start;
    if ((step > 0 && span < 0) || (step < 0 && span > 0)) return 0;
    double steps = span / step;
    if (!(steps < cap)) return static_cast<std::uint64_t>(cap);
    auto n = static_cast<std::uint64_t>(std::floor(steps));
    // Tolerate rounding in fractional steps ([0:0.1:0.3] has 4 elements):
    // the next element counts when it lands on `end` up to rounding.
    double next = start + static_cast<double>(n + 1) * step;
    double tol = 1e-9 * std::abs(step);
    if (std::abs(next - end) <= tol) ++n;
    return n + 1;
}

const char* type_name(ValueType t) {
    switch (t) {
        case ValueType::Undef: return "undef";
        case ValueType::Bool: return "bool";
        case ValueType::Number: return "number";
        case ValueType::String: return "string";
        case ValueType::List: return "list";
        case ValueType::Range: return "range";
        case ValueType::Function: return "function";
    }
    return "value";
}

Value Value::string(std::string s) {
    Value v;
    new (&v.u_.str) StrPtr(std::make_shared<const std::string>(std::move(s)));
    v.tag_ = ValueType::String;
    return v;
}

Value Value::list(ValueList items) {
    Value v;
    new (&v.u_.list) ListPtr(std::make_shared<const ValueList>(std::move(items)));
    v.tag_ = ValueType::List;
    return v;
}

Value Value::function(ClosurePtr f) {
    Value v;
    new (&v.u_.fn) ClosurePtr(std::move(f));
    v.tag_ = ValueType::Function;
    return v;
}

Value Value::list_shared(std::shared_ptr<const ValueList> items) {
    Value v;
    new (&v.u_.list) ListPtr(items ? std::move(items) : std::make_shared<const ValueList>());
    v.tag_ = ValueType::List;
    return v;
}

void Value::copy_shared(const Value& o) {
    switch (o.tag_) {
        case ValueType::String: new (&u_.str) StrPtr(o.u_.str); break;
        case ValueType::List: new (&u_.list) ListPtr(o.u_.list); break;
        default: new (&u_.fn) ClosurePtr(o.u_.fn); break;
    }
}

void Value::release() noexcept {
    switch (tag_) {
        case ValueType::String: u_.str.~StrPtr(); break;
        case ValueType::List: u_.list.~ListPtr(); break;
        default: u_.fn.~ClosurePtr(); break;
    }
}

void Value::bad_access() { throw std::bad_variant_access(); }

bool Value::truthy() const {
    switch (type()) {
        case ValueType::Undef: return false;
        case ValueType::Bool: return as_bool();
        case ValueType::Number: return as_number() != 0;
        case ValueType::String: return !as_string().empty();
        case ValueType::List: return !as_list().empty();
        case ValueType::Range:
        case ValueType::Function: return true;
    }
    return false;
}

bool Value::operator==(const Value& o) const {
    if (type() != o.type()) return false;
    switch (type()) {
        case ValueType::Undef: return true;
        case ValueType::Bool: return as_bool() == o.as_bool();
        case ValueType::Number: return as_number() == o.as_number();
        case ValueType::String: return as_string() == o.as_string();
        case ValueType::List: {
            const ValueList& a = as_list();
            const ValueList& b = o.as_list();
            if (&a == &b) return true;
            if (a.size() != b.size()) return false;
            for (std::size_t i = 0; i < a.size(); ++i)
                if (a[i] != b[i]) return false;
            return true;
        }
        case ValueType::Range: {
            // Equal when they hold the same elements, as OpenSCAD compares
            // them: two empty ranges are equal, [0:1:3] equals [0:1:3.5].
            const Range& a = as_range();
            const Range& b = o.as_range();
            const std::uint64_t n = a.size();
            if (n != b.size()) return false;
            return n == 0 || (a.start == b.start && a.step == b.step);
        }
        case ValueType::Function: return &as_function() == &o.as_function();
    }
    return false;
}

bool Value::is_vector() const {
    if (!is_list()) return false;
    for (const Value& e : as_list())
        if (!e.is_number()) return false;
    return true;
}

bool Value::is_vector(std::size_t n) const { return is_list() && as_list().size() == n && is_vector(); }

// OpenSCAD 2021's number text (its double-conversion settings): 6
// significant digits, correctly rounded; plain decimals for exponents -5
// to 5 (`0.00001`, `100000`), otherwise `1e-6`, `1e+6`, `1.23457e+8` (no
// padded exponent); trailing zeros dropped; -0 is `0`.
std::string format_number(double n) {
    if (std::isnan(n)) return "nan";
    if (std::isinf(n)) return n > 0 ? "inf" : "-inf";
    if (n == 0) return "0";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.5e", n);  // "-d.ddddde±XX": the 6 digits, rounded once
    std::string_view text(buf);
    const bool negative = text[0] == '-';
    if (negative) text.remove_prefix(1);
    const std::size_t e = text.find('e');
    std::string digits;
    digits += text[0];
    digits += text.substr(2, e - 2);  // 6 digits, no point
    const int exponent = std::atoi(text.data() + e + 1);
    std::string out = negative ? "-" : "";
    auto trimmed = [](std::string s) {
        if (s.find('.') != std::string::npos) {
            while (s.back() == '0') s.pop_back();
            if (s.back() == '.') s.pop_back();
        }
        return s;
    };
    if (exponent < -5 || exponent > 5) {
        out += trimmed(digits.substr(0, 1) + "." + digits.substr(1));
        out += exponent < 0 ? "e-" : "e+";
        out += std::to_string(std::abs(exponent));
    } else if (exponent < 0) {
        out += trimmed("0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits);
    } else {
        const std::size_t point = static_cast<std::size_t>(exponent) + 1;
        out += trimmed(digits.substr(0, point) + "." + digits.substr(point));
    }
    return out;
}

namespace {
// Between quotes as they are, as OpenSCAD prints them: `"q"uote"`.
void append_quoted(std::string& out, const std::string& s) {
    out += '"';
    out += s;
    out += '"';
}

constexpr std::size_t unbounded = static_cast<std::size_t>(-1);

// False once out is longer than max (the text is then incomplete).
bool append(std::string& out, const Value& v, bool quote_strings, std::size_t max) {
    if (out.size() > max) return false;
    switch (v.type()) {
        case ValueType::Undef: out += "undef"; break;
        case ValueType::Bool: out += v.as_bool() ? "true" : "false"; break;
        case ValueType::Number: out += format_number(v.as_number()); break;
        case ValueType::String:
            if (quote_strings) append_quoted(out, v.as_string());
            else out += v.as_string();
            break;
        case ValueType::List: {
            out += '[';
            bool first = true;
            for (const Value& e : v.as_list()) {
                if (!first) out += ", ";
                first = false;
                if (!append(out, e, true, max)) return false;
            }
            out += ']';
            break;
        }
        case ValueType::Range: {
            const Range& r = v.as_range();
            out += '[' + format_number(r.start) + " : " + format_number(r.step) + " : " +
                   format_number(r.end) + ']';
            break;
        }
        case ValueType::Function: out += openscad_text(*v.as_function().literal); break;
    }
    return out.size() <= max;
}
}  // namespace

std::string to_str(const Value& v) {
    std::string out;
    append(out, v, false, unbounded);
    return out;
}

std::string to_repr(const Value& v) {
    std::string out;
    append(out, v, true, unbounded);
    return out;
}

std::optional<std::string> to_str_bounded(const Value& v, std::size_t max_chars) {
    std::string out;
    if (!append(out, v, false, max_chars)) return std::nullopt;
    return out;
}

std::optional<std::string> to_repr_bounded(const Value& v, std::size_t max_chars) {
    std::string out;
    if (!append(out, v, true, max_chars)) return std::nullopt;
    return out;
}

}  // namespace kerf
