// Numeric built-ins of docs/spec.md §2 with OpenSCAD's semantics: trigonometry in
// degrees, exact at the angles people type (sin(180) is 0, not 1.2e-16, so
// rotated grids line up and `==` tests work), log base 10, ln natural,
// round half away from zero. Domain errors such as sqrt(-1) give NaN values
// as in OpenSCAD; the evaluator rejects NaN where geometry needs a number.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "interpreter/builtins/support.hpp"
#include "interpreter/degrees.hpp"

namespace kerf::builtin {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// tan in degrees, as OpenSCAD 2021 computes it: x is brought into [0, 180)
// by whole half turns (cycles), then 0, 30, 45, 60 and 90 and their
// supplements are exact; 0 is -0 and 90 is -inf after an odd number of
// half turns (tan(-180) is -0, tan(-90) is -inf, tan(90) is +inf).
double tan_deg(double x) {
    if (!std::isfinite(x)) return kNaN;
    const double cycles = std::floor(x / 180.0);
    const bool odd = std::fmod(cycles, 2.0) != 0;
    if (!(x >= 0 && x < 180.0)) x -= 180.0 * cycles;
    const bool oppose = x > 90.0;
    if (oppose) x = 180.0 - x;
    double t;
    if (x == 0) t = odd ? -0.0 : 0.0;
    else if (x == 30) t = std::numbers::inv_sqrt3;
    else if (x == 45) t = 1;
    else if (x == 60) t = std::numbers::sqrt3;
    else if (x == 90) t = odd ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    else t = std::tan(x * (std::numbers::pi / 180.0));
    return oppose ? -t : t;
}

double to_degrees(double r) { return r * (180.0 / std::numbers::pi); }  // OpenSCAD: x * M_RAD2DEG

// The inverse functions as OpenSCAD 2021's: the nearest whole degree when
// the forward function gives x back there exactly (asin(0.5) is 30,
// atan(1) is 45), the computed angle otherwise.
template <double (*Inverse)(double), double (*Forward)(double)>
double inverse_deg(double x) {
    const double d = to_degrees(Inverse(x));
    const double whole = std::round(d);
    return Forward(whole) == x ? whole : d;
}
double asin_(double x) { return std::asin(x); }
double acos_(double x) { return std::acos(x); }
double atan_(double x) { return std::atan(x); }
double asin_deg(double x) { return inverse_deg<asin_, sin_deg>(x); }
double acos_deg(double x) { return inverse_deg<acos_, cos_deg>(x); }
double atan_deg(double x) { return inverse_deg<atan_, tan_deg>(x); }
// atan2: the nearest whole degree when within 3e-14 of it.
double atan2_deg(double y, double x) {
    const double d = to_degrees(std::atan2(y, x));
    const double whole = std::round(d);
    return std::abs(d - whole) < 3.0e-14 ? whole : d;
}

template <double (*F)(double)>
Value unary(std::span<const Value> args, const BuiltinContext& ctx, std::string_view name) {
    expect_count(args, ctx, name, 1);
    return Value(F(number_arg(args, 0, ctx, name)));
}

double sqrt_(double x) { return std::sqrt(x); }
double exp_(double x) { return std::exp(x); }
double ln_(double x) { return std::log(x); }
double abs_(double x) { return std::abs(x); }
double sign_(double x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : std::isnan(x) ? x : 0.0; }
double floor_(double x) { return std::floor(x); }
double ceil_(double x) { return std::ceil(x); }
double round_(double x) { return std::round(x); }  // half away from zero

#define KERF_UNARY(name, param, f) \
    Entry { #name, param, [](std::span<const Value> a, const BuiltinContext& c) { return unary<f>(a, c, #name); } }

Value atan2_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "atan2", 2);
    return Value(atan2_deg(number_arg(args, 0, ctx, "atan2"), number_arg(args, 1, ctx, "atan2")));
}

Value pow_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "pow", 2);
    return Value(std::pow(number_arg(args, 0, ctx, "pow"), number_arg(args, 1, ctx, "pow")));
}

// log(x) is base 10; log(b, x) is base b (OpenSCAD's two-argument form).
Value log_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "log", 1, 2);
    if (args.size() == 1) return Value(std::log10(number_arg(args, 0, ctx, "log")));
    return Value(std::log(number_arg(args, 1, ctx, "log")) / std::log(number_arg(args, 0, ctx, "log")));
}

// min/max of several numbers, or of the elements of one list.
template <bool IsMin>
Value extremum(std::span<const Value> args, const BuiltinContext& ctx) {
    constexpr std::string_view name = IsMin ? "min" : "max";
    if (args.empty()) fail(ctx, std::string(name) + ": expected a list or at least one number, got no arguments");
    std::span<const Value> items = args;
    const bool from_list = args.size() == 1 && args[0].is_list();
    if (from_list) items = args[0].as_list();
    if (items.empty()) fail(ctx, std::string(name) + ": the list is empty");
    double best = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items[i].is_number()) {
            std::string where = from_list ? "element " + std::to_string(i) + " of the list: "
                                : items.size() > 1 ? "argument " + std::to_string(i + 1) + ": " : "";
            fail(ctx, std::string(name) + ": " + where + "expected a number, got " + describe(items[i]));
        }
        double x = items[i].as_number();
        if (i == 0 || (IsMin ? x < best : x > best)) best = x;
    }
    return Value(best);
}

const std::vector<double>& vector_arg(std::span<const Value> args, std::size_t i, const BuiltinContext& ctx,
                                      std::string_view fn, std::vector<double>& out) {
    const Value& v = args[i];
    if (!v.is_vector()) {
        std::string where = args.size() > 1 ? "argument " + std::to_string(i + 1) + ": " : "";
        fail(ctx, std::string(fn) + ": " + where + "expected a vector (a list of numbers), got " + describe(v));
    }
    out.clear();
    for (const Value& e : v.as_list()) out.push_back(e.as_number());
    return out;
}

Value norm_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "norm", 1);
    std::vector<double> v;
    vector_arg(args, 0, ctx, "norm", v);
    // Scaled sum of squares: no overflow for components near 1e200.
    double scale = 0;
    for (double x : v) scale = std::max(scale, std::abs(x));
    if (scale == 0 || !std::isfinite(scale)) return Value(scale);
    double sum = 0;
    for (double x : v) sum += (x / scale) * (x / scale);
    return Value(scale * std::sqrt(sum));
}

// cross of two 3-vectors is a 3-vector; of two 2-vectors, as in OpenSCAD,
// the z component of their 3D cross product (a number).
Value cross_fn(std::span<const Value> args, const BuiltinContext& ctx) {
    expect_count(args, ctx, "cross", 2);
    std::vector<double> a, b;
    vector_arg(args, 0, ctx, "cross", a);
    vector_arg(args, 1, ctx, "cross", b);
    for (const std::vector<double>* v : {&a, &b})
        for (double x : *v)
            if (!std::isfinite(x))  // OpenSCAD: undef
                fail(ctx, std::string("Invalid value (") + (std::isnan(x) ? "NaN" : "INF") +
                              ") in parameter vector for cross()");
    if (a.size() == 2 && b.size() == 2) return Value(a[0] * b[1] - a[1] * b[0]);
    if (a.size() != 3 || b.size() != 3)
        fail(ctx, "cross: expected two 3-vectors or two 2-vectors, got lengths " + std::to_string(a.size()) +
                      " and " + std::to_string(b.size()));
    return Value::list({Value(a[1] * b[2] - a[2] * b[1]), Value(a[2] * b[0] - a[0] * b[2]),
                        Value(a[0] * b[1] - a[1] * b[0])});
}

const Entry kEntries[] = {
    KERF_UNARY(sin, "degrees", sin_deg),
    KERF_UNARY(cos, "degrees", cos_deg),
    KERF_UNARY(tan, "degrees", tan_deg),
    KERF_UNARY(asin, "x", asin_deg),
    KERF_UNARY(acos, "x", acos_deg),
    KERF_UNARY(atan, "x", atan_deg),
    {"atan2", "y x", atan2_fn},
    KERF_UNARY(sqrt, "x", sqrt_),
    {"pow", "base exponent", pow_fn},
    KERF_UNARY(exp, "x", exp_),
    KERF_UNARY(ln, "x", ln_),
    {"log", "x | base x", log_fn},
    KERF_UNARY(abs, "x", abs_),
    KERF_UNARY(sign, "x", sign_),
    {"min", "...", extremum<true>},
    {"max", "...", extremum<false>},
    KERF_UNARY(floor, "x", floor_),
    KERF_UNARY(ceil, "x", ceil_),
    KERF_UNARY(round, "x", round_),
    {"norm", "v", norm_fn},
    {"cross", "x y", cross_fn},
};

}  // namespace

std::span<const Entry> math_entries() { return kEntries; }

}  // namespace kerf::builtin
