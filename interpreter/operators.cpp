#include "interpreter/operators.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "grammar/text_check.hpp"

namespace kerf {

double number_op(char op, double x, double y) {
    switch (op) {
        case '+': return x + y;
        case '-': return x - y;
        case '*': return x * y;
        case '/': return x / y;
        case '%': return std::fmod(x, y);
        default: return std::pow(x, y);
    }
}

namespace {

[[noreturn]] void type_error(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc) {
    throw SoftError(loc, "cannot apply '" + std::string(op) + "' to " + a.type_name() + " and " +
                               b.type_name());
}

[[noreturn]] void length_error(std::string_view op, std::size_t n, std::size_t m, const SourceLoc& loc) {
    throw SoftError(loc, "'" + std::string(op) + "' needs lists of equal length (got " +
                               std::to_string(n) + " and " + std::to_string(m) + ")");
}

void spend(OpBudget* b, std::size_t n, const SourceLoc& loc) {
    if (b) b->make(n, loc);
}

void walk(OpBudget* b, std::uint64_t n) {
    if (b) b->walk(n);
}

// Values in a (possibly shared) list tree, counting stops past cap: lets an
// operation refuse an exponentially large operand before building anything.
std::uint64_t tree_size(const Value& v, std::uint64_t cap, std::uint64_t n = 0) {
    if (!v.is_list()) return n;
    for (const Value& e : v.as_list()) {
        if (++n > cap) return n;
        n = tree_size(e, cap, n);
        if (n > cap) return n;
    }
    return n;
}

std::uint64_t precheck(OpBudget* b, const Value& v, const SourceLoc& loc) {
    return b ? checked_tree_size(*b, v, loc) : 0;
}

double num_op(char op, double x, double y) { return number_op(op, x, y); }

// Element-wise + and - on numbers or (nested) lists of equal shape.
Value elementwise(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, OpBudget* budget) {
    if (a.is_number() && b.is_number()) return Value(num_op(op[0], a.as_number(), b.as_number()));
    if (!a.is_list() || !b.is_list()) type_error(op, a, b, loc);
    const ValueList& x = a.as_list();
    const ValueList& y = b.as_list();
    if (x.size() != y.size()) length_error(op, x.size(), y.size(), loc);
    spend(budget, x.size(), loc);
    ValueList out;
    out.reserve(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) out.push_back(elementwise(op, x[i], y[i], loc, budget));
    return Value::list(std::move(out));
}

// list op scalar (or scalar op list when scalar_left), recursively.
Value scale_list(char op, const Value& v, double s, bool scalar_left, const Value& a, const Value& b,
                 const SourceLoc& loc, OpBudget* budget) {
    if (v.is_number())
        return Value(scalar_left ? num_op(op, s, v.as_number()) : num_op(op, v.as_number(), s));
    if (!v.is_list()) type_error(std::string(1, op), a, b, loc);
    spend(budget, v.as_list().size(), loc);
    ValueList out;
    out.reserve(v.as_list().size());
    for (const Value& e : v.as_list()) out.push_back(scale_list(op, e, s, scalar_left, a, b, loc, budget));
    return Value::list(std::move(out));
}

bool all_lists(const ValueList& l) {
    for (const Value& e : l)
        if (!e.is_list()) return false;
    return true;
}

// The products a multiplication of lists computes, charged on leaving it
// as a quarter of an element each: a multiply-add costs about a quarter
// of making an element (measured, docs/language.md §13), and a 4x4
// matrix product costs 2 steps.
struct Products {
    OpBudget* budget;
    std::uint64_t n = 0;
    ~Products() { walk(budget, n / 4); }
    // k more, counted before they are computed: past the work cap the
    // product stops (a 1000x1000 matrix squared is 10^9 of them).
    void add(std::uint64_t k) {
        n += k;
        if (budget && budget->used + budget->walked + n / 4 > budget->work_cap) throw WorkCapReached{};
    }
};

double dot(const ValueList& x, const ValueList& y, const Value& a, const Value& b, const SourceLoc& loc,
           Products& products) {
    if (x.size() != y.size()) length_error("*", x.size(), y.size(), loc);
    products.add(x.size());
    double s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!x[i].is_number() || !y[i].is_number()) type_error("*", a, b, loc);
        s += x[i].as_number() * y[i].as_number();
    }
    return s;
}

// vector·vector, matrix·vector, vector·matrix, matrix·matrix.
Value multiply_lists(const Value& a, const Value& b, const SourceLoc& loc, OpBudget* budget) {
    const ValueList& x = a.as_list();
    const ValueList& y = b.as_list();
    Products products{budget};
    // Two vectors of one length, the common case, in one walk that checks
    // the types as it goes (three walks otherwise).
    if (x.size() == y.size()) {
        double s = 0;
        std::size_t i = 0;
        for (; i < x.size() && x[i].is_number() && y[i].is_number(); ++i) s += x[i].as_number() * y[i].as_number();
        products.n += i;
        if (i == x.size()) return Value(s);
    }
    bool a_vec = a.is_vector(), b_vec = b.is_vector();
    bool a_mat = !x.empty() && all_lists(x), b_mat = !y.empty() && all_lists(y);
    if (a_vec && b_vec) return Value(dot(x, y, a, b, loc, products));
    if (a_mat && b_vec) {
        spend(budget, x.size(), loc);
        ValueList out;
        out.reserve(x.size());
        for (const Value& row : x) out.push_back(Value(dot(row.as_list(), y, a, b, loc, products)));
        return Value::list(std::move(out));
    }
    if (b_mat) {
        // Columns of b: every row must have the same length.
        std::size_t cols = y[0].as_list().size();
        for (const Value& row : y) {
            if (!row.is_vector()) type_error("*", a, b, loc);
            if (row.as_list().size() != cols) throw SoftError(loc, "'*' needs a matrix with rows of equal length");
        }
        auto times_vector = [&](const ValueList& v) {
            if (v.size() != y.size()) length_error("*", v.size(), y.size(), loc);
            spend(budget, cols, loc);
            products.add(static_cast<std::uint64_t>(cols) * v.size());
            ValueList out;
            out.reserve(cols);
            for (std::size_t j = 0; j < cols; ++j) {
                double s = 0;
                for (std::size_t i = 0; i < v.size(); ++i) {
                    if (!v[i].is_number()) type_error("*", a, b, loc);
                    s += v[i].as_number() * y[i].as_list()[j].as_number();
                }
                out.push_back(Value(s));
            }
            return Value::list(std::move(out));
        };
        if (a_vec) return times_vector(x);
        if (a_mat) {
            ValueList out;
            out.reserve(x.size());
            for (const Value& row : x) out.push_back(times_vector(row.as_list()));
            return Value::list(std::move(out));
        }
    }
    type_error("*", a, b, loc);
}

int compare(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, bool& unordered,
            OpBudget* budget) {
    unordered = false;
    if (a.is_number() && b.is_number()) {
        double x = a.as_number(), y = b.as_number();
        if (std::isnan(x) || std::isnan(y)) unordered = true;
        return x < y ? -1 : (x > y ? 1 : 0);
    }
    if (a.is_string() && b.is_string()) {
        walk(budget, std::min(a.as_string().size(), b.as_string().size()) / 16);
        const int c = a.as_string().compare(b.as_string());
        return (c > 0) - (c < 0);
    }
    if (a.is_bool() && b.is_bool()) return int(a.as_bool()) - int(b.as_bool());
    type_error(op, a, b, loc);
}

}  // namespace

Value unary_op(std::string_view op, const Value& a, const SourceLoc& loc, OpBudget* budget) {
    if (a.is_number()) return Value(op == "-" ? -a.as_number() : a.as_number());
    if (a.is_list()) {
        if (budget && budget->used == 0) precheck(budget, a, loc);
        spend(budget, a.as_list().size(), loc);
        ValueList out;
        out.reserve(a.as_list().size());
        for (const Value& e : a.as_list()) out.push_back(unary_op(op, e, loc, budget));
        return Value::list(std::move(out));
    }
    throw SoftError(loc, "cannot apply unary '" + std::string(op) + "' to " + a.type_name());
}

void OpBudget::make(std::uint64_t n, const SourceLoc& loc) {
    used += n;
    if (used > limit) throw SourceError(loc, "list size limit " + std::to_string(limit) + " exceeded");
}

std::uint64_t checked_tree_size(OpBudget& budget, const Value& v, const SourceLoc& loc) {
    if (!v.is_list()) return 0;
    const std::uint64_t n = tree_size(v, budget.limit);
    if (n > budget.limit) throw SourceError(loc, "list size limit " + std::to_string(budget.limit) + " exceeded");
    return n;
}

Value binary_op(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, OpBudget* budget) {
    if (op == "==" || op == "!=") {
        // Shared nested lists could make the comparison exponentially long:
        // both trees are sized (and charged, as walked) first; the
        // comparison then walks the smaller at most, the bytes of two
        // strings alike.
        walk(budget, precheck(budget, a, loc) + precheck(budget, b, loc));
        if (a.is_string() && b.is_string()) walk(budget, std::min(a.as_string().size(), b.as_string().size()) / 16);
        return Value((a == b) == (op == "=="));
    }
    if (op == "<" || op == "<=" || op == ">" || op == ">=") {
        bool unordered;
        int c = compare(op, a, b, loc, unordered, budget);
        if (unordered) return Value(false);
        if (op == "<") return Value(c < 0);
        if (op == "<=") return Value(c <= 0);
        if (op == ">") return Value(c > 0);
        return Value(c >= 0);
    }
    if (op.size() != 1) throw SourceError(loc, "unknown operator '" + std::string(op) + "'");
    char o = op[0];
    if (a.is_number() && b.is_number()) return Value(num_op(o, a.as_number(), b.as_number()));
    precheck(budget, a, loc);
    precheck(budget, b, loc);
    switch (o) {
        case '+':
        case '-': return elementwise(op, a, b, loc, budget);
        case '*':
            if (a.is_list() && b.is_number()) return scale_list('*', a, b.as_number(), false, a, b, loc, budget);
            if (a.is_number() && b.is_list()) return scale_list('*', b, a.as_number(), true, a, b, loc, budget);
            if (a.is_list() && b.is_list()) return multiply_lists(a, b, loc, budget);
            break;
        case '/':
            if (a.is_list() && b.is_number()) return scale_list('/', a, b.as_number(), false, a, b, loc, budget);
            break;
        default: break;
    }
    type_error(op, a, b, loc);
}

namespace {
std::size_t char_bytes(unsigned char lead) {
    return lead < 0xC0 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : lead < 0xF8 ? 4 : lead < 0xFC ? 5 : lead < 0xFE ? 6 : 1;
}

// Bytes below 0x80 from `from` on, 8 at a time, stopping before `limit`
// bytes: a run of ASCII characters is that many characters, so len() and
// s[i] skip it ~8 times faster than the walk below.
std::size_t ascii_run(std::string_view s, std::size_t from, std::size_t limit) {
    std::size_t i = from;
    while (i + 8 <= s.size() && i + 8 - from <= limit) {
        std::uint64_t w;
        std::memcpy(&w, s.data() + i, 8);
        if (w & 0x8080808080808080ull) break;
        i += 8;
    }
    return i - from;
}

// Calls f(i, n) for each character at s[i, i + n); stops when f is false.
template <class F>
void walk_characters(std::string_view s, F f, std::size_t start = 0) {
    for (std::size_t i = start; i < s.size();) {
        const std::size_t n = char_bytes(static_cast<unsigned char>(s[i]));
        if (n > s.size() - i || !f(i, n)) return;
        i += n;
    }
}
}  // namespace

std::vector<std::string_view> characters(std::string_view s) {
    std::vector<std::string_view> out;
    walk_characters(s, [&](std::size_t i, std::size_t n) {
        out.push_back(s.substr(i, n));
        return true;
    });
    return out;
}

std::size_t utf8_length(std::string_view s) {
    std::size_t count = ascii_run(s, 0, s.size());
    walk_characters(s, [&](std::size_t, std::size_t) { return ++count; }, count);
    return count;
}

std::optional<std::string_view> character_at(std::string_view s, std::size_t i) {
    std::size_t count = ascii_run(s, 0, i);
    std::optional<std::string_view> piece;
    walk_characters(
        s,
        [&](std::size_t at, std::size_t n) {
            if (count++ < i) return true;
            piece = s.substr(at, n);
            return false;
        },
        count);
    return piece;
}

bool valid_utf8(std::string_view s) {
    for (std::size_t i = 0, n = 0; i < s.size(); i += n)
        if ((n = grammar::utf8_sequence_length(s, i)) == 0) return false;
    return true;
}

Value index_value(const Value& object, const Value& index, const SourceLoc& loc) {
    if (!index.is_number())
        throw SourceError(loc, std::string("index must be a number, got ") + index.type_name());
    double d = index.as_number();
    if (d != std::floor(d)) throw SourceError(loc, "index " + format_number(d) + " is not an integer");
    auto out_of_range = [&](std::uint64_t len) {
        return SourceError(loc, "index " + format_number(d) + " out of range (length " + std::to_string(len) + ")");
    };
    if (object.is_list()) {
        const ValueList& l = object.as_list();
        if (d < 0 || d >= static_cast<double>(l.size())) throw out_of_range(l.size());
        return l[static_cast<std::size_t>(d)];
    }
    if (object.is_range()) {
        std::uint64_t n = object.as_range().size();
        if (d < 0 || d >= static_cast<double>(n)) throw out_of_range(n);
        return Value(object.as_range().at(static_cast<std::uint64_t>(d)));
    }
    if (object.is_string()) {
        const std::string& s = object.as_string();
        // One walk (the length only for the error): s[i] in a loop over a
        // long string walks it once per index.
        const std::optional<std::string_view> piece =
            d < 0 || d >= static_cast<double>(s.size()) ? std::nullopt : character_at(s, static_cast<std::size_t>(d));
        if (!piece) throw out_of_range(utf8_length(s));
        return Value::string(std::string(*piece));
    }
    throw SourceError(loc, std::string("cannot index a ") + object.type_name());
}

}  // namespace kerf
