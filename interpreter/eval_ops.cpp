// Operators, ranges, indexing and members: a value from values, the
// budget of the lists an operator makes or reads, and OpenSCAD's answers
// where the strict one fails (openscad_ops.cpp).
#include <cmath>
#include <string>
#include <string_view>
#include <utility>

#include "interpreter/evaluator.hpp"
#include "interpreter/openscad_ops.hpp"
#include "interpreter/operators.hpp"

namespace kerf::eval {

Value Evaluator::lenient_operator(const ast::Expr& e, const Value& a, const Value* b, const OpBudget& tried) {
    OpBudget budget{tried.limit};
    budget.walk(tried.used + tried.walked);
    budget.work_cap = work_cap();
    std::string warning;
    Value v;
    try {
        v = b ? openscad_binary(e.text, a, *b, e.loc, warning, budget)
              : openscad_unary(e.text, a, e.loc, warning, budget);
    } catch (const WorkCapReached&) {
        count_work(budget.used + budget.walked, e.loc);  // past the limit: throws
        throw;
    }
    count_work(budget.used + budget.walked, e.loc);
    if (!warning.empty()) warn(e.loc, std::move(warning));
    return v;
}

Value Evaluator::eval_range(const ast::Expr& e, Scope& s) {
    double v[3];
    bool finite = true;
    for (std::size_t i = 0; i < e.items.size() && i < 3; ++i) {
        Value x = eval(*e.items[i], s);
        if (lenient_ && !x.is_number()) return Value();  // OpenSCAD: undef
        if (!x.is_number()) throw SourceError(e.items[i]->loc, std::string("range bound must be a number, got ") + x.type_name());
        if (!lenient_ && !std::isfinite(x.as_number())) throw SourceError(e.items[i]->loc, "range bound must be finite, got " + format_number(x.as_number()));
        v[i] = x.as_number();
        finite = finite && std::isfinite(v[i]);
    }
    // OpenSCAD makes a range of any numbers: `[0 : 1 : inf]` echoes as
    // such, a loop over it runs no pass with its "too many elements"
    // warning, one of NaN none, `[inf : 1 : inf]` one (Range::size,
    // openscad_range_count; docs/openscad.md, "Ranges").
    if (e.items.size() == 2) {
        // OpenSCAD 2021 counts [5:1] down as [1:1:5] (docs/openscad.md, "Ranges").
        if (lenient_ && v[0] > v[1]) {
            warn(e.loc, "Using ranges of the form [begin:end] with begin value greater than the end value is deprecated");
            std::swap(v[0], v[1]);
        }
        return Value::range(v[0], 1, v[1]);
    }
    // OpenSCAD makes [a : 0 : b]; its loops then run no pass (iteration_count).
    if (v[1] == 0 && !lenient_) throw SourceError(e.items[1]->loc, "range step must not be 0");
    // A step pointing away from the end: empty in both dialects, and
    // OpenSCAD says so where the range is made.
    // (Not for a field that is not finite: OpenSCAD is silent there.)
    if (lenient_ && finite && v[0] < v[2] && v[1] < 0) warn(e.loc, "begin is smaller than the end, but step is negative");
    if (lenient_ && finite && v[0] > v[2] && v[1] > 0) warn(e.loc, "begin is greater than the end, but step is positive");
    return Value::range(v[0], v[1], v[2]);
}

Value Evaluator::eval_unary(const ast::Expr& e, Scope& s) {
    Value a = eval(*e.items[0], s);
    const std::string_view op = e.text;
    if (op == "!") return Value(!a.truthy());
    if (a.is_number()) return Value(op == "-" ? -a.as_number() : a.as_number());  // unary_op's first answer
    OpBudget budget{opt_.limits.list_elements};
    // OpenSCAD's undef operand (the usual warning in a loop) goes
    // straight to its answer: the strict refusal costs a throw.
    if (lenient_ && a.is_undef()) return lenient_operator(e, a, nullptr, budget);
    Value v;
    try {
        v = unary_op(e.text, a, e.loc, &budget);
    } catch (const SoftError&) {
        if (!lenient_) throw;
        return lenient_operator(e, a, nullptr, budget);
    }
    count_work(budget.used + budget.walked, e.loc);
    return v;
}

Value Evaluator::eval_binary(const ast::Expr& e, Scope& s) {
    const std::string& op = e.text;  // compared by its characters: no call
    if (op.size() == 2 && op[0] == op[1] && (op[0] == '&' || op[0] == '|')) {
        const bool first = eval(*e.items[0], s).truthy();
        if (op[0] == '&') return Value(first && eval(*e.items[1], s).truthy());
        return Value(first || eval(*e.items[1], s).truthy());
    }
    Value a = eval(*e.items[0], s);
    Value b = eval(*e.items[1], s);
    // Arithmetic on two numbers, as binary_op answers it first (it
    // charges nothing for numbers): a loop's `(i + 0.5) * 0.2`
    // without a budget or a dispatch on the operator's text.
    if (op.size() == 1 && a.is_number() && b.is_number() && op[0] != '<' && op[0] != '>') {
        const double x = a.as_number(), y = b.as_number();
        switch (op[0]) {  // number_op's common cases, inline
            case '+': return Value(x + y);
            case '-': return Value(x - y);
            case '*': return Value(x * y);
            case '/': return Value(x / y);
            default: return Value(number_op(op[0], x, y));
        }
    }
    return binary_values(e, a, b);
}

// A binary operator on values that are not two numbers: the budget of the
// lists it makes or reads, and OpenSCAD's answers where the strict one fails.
Value Evaluator::binary_values(const ast::Expr& e, const Value& a, const Value& b) {
    OpBudget budget{opt_.limits.list_elements};
    if (lenient_ && (a.is_undef() || b.is_undef()) && !a.is_list() && !b.is_list() && e.text != "==" &&
        e.text != "!=")
        return lenient_operator(e, a, &b, budget);
    budget.work_cap = work_cap();
    Value v;
    try {
        v = binary_op(e.text, a, b, e.loc, &budget);
    } catch (const SoftError&) {
        if (!lenient_) throw;
        return lenient_operator(e, a, &b, budget);
    } catch (const WorkCapReached&) {
        count_work(budget.used + budget.walked, e.loc);  // past the limit: throws
        throw;
    }
    // Lists made, or only read (compared, multiplied in a dot product).
    count_work(budget.used + budget.walked, e.loc);
    return v;
}

Value Evaluator::eval_index(const ast::Expr& e, Scope& s) {
    Value obj = eval(*e.items[0], s);
    Value idx = eval(*e.items[1], s);
    // A string's i-th character is found walking it (UTF-8) up to
    // there: charged i + 1 bytes, a lower bound (the walk takes up
    // to 4 bytes a character where they are not ASCII), the whole
    // string for an index past its end.
    if (obj.is_string() && idx.is_number() && !(idx.as_number() < 0)) {
        const double i = idx.as_number();
        const std::uint64_t n = obj.as_string().size();
        count_work((i + 1 < double(n) ? std::uint64_t(i) + 1 : n) / 16, e.loc);
    }
    if (lenient_) return openscad_index(obj, idx);
    return index_value(obj, idx, e.loc);
}

Value Evaluator::eval_member(const ast::Expr& e, Scope& s) {
    Value obj = eval(*e.items[0], s);
    int i = e.text == "x" ? 0 : e.text == "y" ? 1 : e.text == "z" ? 2 : -1;
    if (i < 0 && lenient_) {  // OpenSCAD 2021: undef, silently
        warn(e.loc, "unknown member '." + e.text + "' is undef (OpenSCAD 2021 knows .x, .y and .z)");
        return Value();
    }
    if (i < 0) throw SourceError(e.loc, "unknown member '." + e.text + "'");
    if (lenient_) return openscad_index(obj.is_list() ? obj : Value(), Value(i));
    if (!obj.is_list()) throw SourceError(e.loc, "'." + e.text + "' needs a list, got " + obj.type_name());
    return index_value(obj, Value(i), e.loc);
}

}  // namespace kerf::eval
