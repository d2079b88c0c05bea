#include "interpreter/openscad_ops.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "interpreter/operators.hpp"

namespace kerf {

const char* openscad_type_name(const Value& v) {
    switch (v.type()) {
        case ValueType::Undef: return "undefined";
        case ValueType::Bool: return "bool";
        case ValueType::Number: return "number";
        case ValueType::String: return "string";
        case ValueType::List: return "vector";
        case ValueType::Range: return "range";
        case ValueType::Function: return "function";
    }
    return "undefined";
}

namespace {

const SourceLoc kNowhere{};

std::string undefined_operation(std::string_view op, const Value& a, const Value& b) {
    return std::string("undefined operation (") + openscad_type_name(a) + " " + std::string(op) + " " +
           openscad_type_name(b) + ")";
}

// a < b as OpenSCAD's Value::operator<: same-type scalars compare, vectors
// lexicographically (a shorter prefix is less); anything else is undef.
// (The caller bounds the trees with checked_tree_size: each pair is
// compared twice at most, so the walk is linear in the smaller one.)
Value less(const Value& a, const Value& b, std::string& warning, OpBudget& budget) {
    if (a.is_list() && b.is_list()) {
        const ValueList& x = a.as_list();
        const ValueList& y = b.as_list();
        std::size_t i = 0;
        for (; i < x.size() && i < y.size(); ++i) {
            budget.walk(1);
            if (x[i].is_number() && y[i].is_number()) {  // the common case, without a Value made
                const double p = x[i].as_number(), q = y[i].as_number();
                if (p < q) return Value(true);
                if (q < p) return Value(false);
                continue;  // equal, or NaN: neither is less, as below
            }
            Value t = less(x[i], y[i], warning, budget);
            if (t.is_undef()) return t;
            if (t.as_bool()) return Value(true);
            Value u = less(y[i], x[i], warning, budget);
            if (u.is_bool() && u.as_bool()) return Value(false);
        }
        return Value(i == x.size() && i < y.size());
    }
    if (a.is_number() && b.is_number()) return Value(a.as_number() < b.as_number());  // NaN: false, as binary_op
    if (a.type() == b.type() && !a.is_undef() && !a.is_range()) {
        try {
            return binary_op("<", a, b, kNowhere, &budget);
        } catch (const SoftError&) {
        }
    }
    warning = undefined_operation("<", a, b);
    return Value();
}

// Two ranges as OpenSCAD's RangeType orders them: an empty one (no
// element) below any other, then by begin, step and element count.
Value compare_ranges(std::string_view op, const Range& a, const Range& b) {
    const std::uint32_t n1 = openscad_range_count(a), n2 = openscad_range_count(b);
    int c;
    if (n1 == 0 || n2 == 0) c = (n1 != 0) - (n2 != 0);
    else if (a.start != b.start) c = a.start < b.start ? -1 : 1;
    else if (a.step != b.step) c = a.step < b.step ? -1 : 1;
    else c = (n1 > n2) - (n1 < n2);
    return Value(op == "<" ? c < 0 : op == ">" ? c > 0 : op == "<=" ? c <= 0 : c >= 0);
}

Value compare(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, std::string& warning,
              OpBudget& budget) {
    if (a.is_range() && b.is_range()) return compare_ranges(op, a.as_range(), b.as_range());
    budget.walk(std::min(checked_tree_size(budget, a, loc), checked_tree_size(budget, b, loc)));
    Value r;
    if (op == "<") r = less(a, b, warning, budget);
    else if (op == ">") r = less(b, a, warning, budget);
    else if (op == "<=") {
        r = less(b, a, warning, budget);
        if (!r.is_undef()) r = Value(!r.as_bool());
    } else {
        r = less(a, b, warning, budget);
        if (!r.is_undef()) r = Value(!r.as_bool());
    }
    if (r.is_undef()) warning = undefined_operation(op, a, b);
    return r;
}

// + and - of two vectors: element-wise up to the shorter length; an element
// pair that does not add is undef (OpenSCAD prints nothing for it).
Value add_lists(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, OpBudget& budget) {
    const ValueList& x = a.as_list();
    const ValueList& y = b.as_list();
    budget.make(std::min(x.size(), y.size()), loc);
    const bool plus = op == "+";
    ValueList out;
    out.reserve(std::min(x.size(), y.size()));
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (x[i].is_list() && y[i].is_list()) {
            out.push_back(add_lists(op, x[i], y[i], loc, budget));
            continue;
        }
        if (x[i].is_number() && y[i].is_number()) {  // the common case, without a call
            const double p = x[i].as_number(), q = y[i].as_number();
            out.push_back(Value(plus ? p + q : p - q));
            continue;
        }
        try {
            out.push_back(binary_op(op, x[i], y[i], kNowhere));
        } catch (const SoftError&) {
            out.push_back(Value());
        }
    }
    return Value::list(std::move(out));
}

}  // namespace

Value openscad_binary(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, std::string& warning,
                      OpBudget& budget) {
    warning.clear();
    if (op == "<" || op == ">" || op == "<=" || op == ">=") return compare(op, a, b, loc, warning, budget);
    if ((op == "+" || op == "-") && a.is_list() && b.is_list()) return add_lists(op, a, b, loc, budget);
    if (a.is_list()) budget.walk(a.as_list().size());  // is_vector below
    if (b.is_list()) budget.walk(b.as_list().size());
    if (op == "*" && a.is_vector() && b.is_vector() && a.as_list().size() != b.as_list().size()) {
        warning = "vector*vector requires matching lengths (" + std::to_string(a.as_list().size()) +
                  " != " + std::to_string(b.as_list().size()) + ")";
        return Value();
    }
    if (op == "/" && a.is_number() && b.is_list()) {  // 2 / [1, 4] is [2, 0.5], nested lists alike
        budget.make(b.as_list().size(), loc);
        ValueList out;
        out.reserve(b.as_list().size());
        std::string inner;
        for (const Value& e : b.as_list())
            out.push_back(e.is_number() ? Value(a.as_number() / e.as_number())
                                        : e.is_list() ? openscad_binary(op, a, e, loc, inner, budget) : Value());
        return Value::list(std::move(out));
    }
    warning = undefined_operation(op, a, b);
    return Value();
}

Value openscad_unary(std::string_view op, const Value& a, const SourceLoc& loc, std::string& warning, OpBudget& budget) {
    warning.clear();
    if (op == "+") return a;
    if (a.is_number()) return Value(-a.as_number());
    if (a.is_list()) {
        budget.make(a.as_list().size(), loc);
        ValueList out;
        out.reserve(a.as_list().size());
        std::string inner;
        for (const Value& e : a.as_list()) out.push_back(e.is_number() || e.is_list() ? openscad_unary(op, e, loc, inner, budget) : Value());
        return Value::list(std::move(out));
    }
    warning = std::string("undefined operation (-") + openscad_type_name(a) + ")";
    return Value();
}

std::uint32_t openscad_range_count(const Range& r) {
    constexpr std::uint32_t max = 4294967295u;
    if (std::isnan(r.start) || std::isnan(r.end) || std::isnan(r.step)) return 0;
    if (r.step < 0 ? r.start < r.end : r.start > r.end) return 0;
    if (r.start == r.end || std::isinf(r.step)) return 1;
    if (std::isinf(r.start) || std::isinf(r.end) || r.step == 0) return max;
    // nextafter: a quotient just below a whole number counts it (OpenSCAD's words).
    const double steps = std::nextafter((r.end - r.start) / r.step, double(max));
    return steps >= double(max) ? max : static_cast<std::uint32_t>(steps) + 1;
}

Value openscad_index(const Value& object, const Value& index) {
    if (!index.is_number()) return Value();
    double d = index.as_number();
    if (!(d >= 0) || d >= 4294967296.0) return Value();
    const double i = std::floor(d);
    if (object.is_range()) {
        const Range& r = object.as_range();
        if (i == 0) return Value(r.start);
        if (i == 1) return Value(r.step);
        if (i == 2) return Value(r.end);
        return Value();
    }
    if (object.is_string()) {
        const std::string& s = object.as_string();
        if (i >= static_cast<double>(s.size())) return Value();
        const std::optional<std::string_view> piece = character_at(s, static_cast<std::size_t>(i));
        return piece ? Value::string(std::string(*piece)) : Value();
    }
    if (!object.is_list() || i >= static_cast<double>(object.as_list().size())) return Value();
    return object.as_list()[static_cast<std::size_t>(i)];
}

}  // namespace kerf
