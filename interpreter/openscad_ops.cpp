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

// a against b as OpenSCAD's Value::operator< orders them: same-type
// scalars compare, vectors lexicographically (a shorter prefix is less);
// anything else is Undef. OpenSCAD asks a < b, then b < a, of each element
// pair, so equal lists nested d deep take 2^d steps there; one three-way
// answer visits each pair once, so the walk is linear in the smaller tree
// (which the caller bounds with checked_tree_size). NaN is neither less nor
// greater, so Equal, as OpenSCAD goes on to the next element then.
enum class Order { Less, Equal, Greater, Undef };

// Two ranges as OpenSCAD's RangeType orders them: an empty one (no
// element) below any other, then by begin, step and element count.
Order range_order(const Range& a, const Range& b) {
    const std::uint32_t n1 = openscad_range_count(a), n2 = openscad_range_count(b);
    int c;
    if (n1 == 0 || n2 == 0) c = (n1 != 0) - (n2 != 0);
    else if (a.start != b.start) c = a.start < b.start ? -1 : 1;
    else if (a.step != b.step) c = a.step < b.step ? -1 : 1;
    else c = (n1 > n2) - (n1 < n2);
    return c < 0 ? Order::Less : c > 0 ? Order::Greater : Order::Equal;
}

Order order(const Value& a, const Value& b, OpBudget& budget) {
    if (a.is_list() && b.is_list()) {
        const ValueList& x = a.as_list();
        const ValueList& y = b.as_list();
        std::size_t i = 0;
        for (; i < x.size() && i < y.size(); ++i) {
            budget.walk(1);
            if (x[i].is_number() && y[i].is_number()) {  // the common case, without a call
                const double p = x[i].as_number(), q = y[i].as_number();
                if (p < q) return Order::Less;
                if (q < p) return Order::Greater;
                continue;
            }
            const Order o = order(x[i], y[i], budget);
            if (o != Order::Equal) return o;
        }
        if (i < y.size()) return Order::Less;
        return i < x.size() ? Order::Greater : Order::Equal;
    }
    if (a.is_number() && b.is_number()) {
        const double p = a.as_number(), q = b.as_number();
        return p < q ? Order::Less : q < p ? Order::Greater : Order::Equal;
    }
    if (a.is_range() && b.is_range()) return range_order(a.as_range(), b.as_range());
    if (a.type() == b.type() && !a.is_undef()) {
        try {
            if (binary_op("<", a, b, kNowhere, &budget).as_bool()) return Order::Less;
            return binary_op("<", b, a, kNowhere, &budget).as_bool() ? Order::Greater : Order::Equal;
        } catch (const SoftError&) {
        }
    }
    return Order::Undef;
}

Value compare(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, std::string& warning,
              OpBudget& budget) {
    budget.walk(checked_tree_size(budget, a, loc) + checked_tree_size(budget, b, loc));  // both are walked
    const Order o = order(a, b, budget);
    if (o == Order::Undef) {
        warning = undefined_operation(op, a, b);
        return Value();
    }
    if (op == "<") return Value(o == Order::Less);
    if (op == ">") return Value(o == Order::Greater);
    if (op == "<=") return Value(o != Order::Greater);
    return Value(o != Order::Less);
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
