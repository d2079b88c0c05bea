#include "interpreter/modules/args.hpp"

#include <cctype>
#include <cmath>

#include "csg/srgb.hpp"
#include "interpreter/modules/colors.hpp"

namespace kerf::eval {

void arg_error(const Args& a, const std::string& message) {
    throw SoftError(a.call->loc, std::string(a.callee) + ": " + message);
}

void arg_unsupported(const Args& a, const std::string& message) {
    throw SourceError(a.call->loc, std::string(a.callee) + ": " + message);
}

namespace {
std::string describe(const Value& v) {
    if (v.is_number()) return format_number(v.as_number());
    if (v.is_string()) return to_repr(v);
    if (v.is_list()) return to_repr(v).size() <= 40 ? to_repr(v) : std::string("a list");
    return v.type_name();
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

std::optional<glm::dvec4> parse_hex(std::string_view s) {
    if (s.empty() || s[0] != '#') return std::nullopt;
    s.remove_prefix(1);
    std::size_t n = s.size();
    if (n != 3 && n != 4 && n != 6 && n != 8) return std::nullopt;
    glm::dvec4 c(0, 0, 0, 1);
    std::size_t per = n <= 4 ? 1 : 2;
    for (std::size_t k = 0; k * per < n; ++k) {
        int v = 0;
        for (std::size_t j = 0; j < per; ++j) {
            int d = hex_digit(s[k * per + j]);
            if (d < 0) return std::nullopt;
            v = v * 16 + d;
        }
        if (per == 1) v *= 17;
        c[static_cast<int>(k)] = v / 255.0;
    }
    return c;
}
}  // namespace

double arg_number(const Args& a, std::size_t i, const char* name, double fallback) {
    if (!a.has(i)) return fallback;
    const Value& v = a[i];
    if (!v.is_number()) arg_error(a, std::string(name) + " must be a number, got " + describe(v));
    if (!std::isfinite(v.as_number())) arg_error(a, std::string(name) + " must be finite, got " + describe(v));
    return v.as_number();
}

double arg_positive(const Args& a, std::size_t i, const char* name, double fallback) {
    double x = arg_number(a, i, name, fallback);
    if (!(x > 0)) arg_error(a, std::string(name) + " must be positive, got " + format_number(x));
    return x;
}

bool arg_bool(const Args& a, std::size_t i, const char* name, bool fallback) {
    if (!a.has(i)) return fallback;
    if (!a[i].is_bool()) arg_error(a, std::string(name) + " must be true or false, got " + describe(a[i]));
    return a[i].as_bool();
}

glm::dvec3 arg_vec3(const Args& a, std::size_t i, const char* name, glm::dvec3 fallback, bool allow2, double z2) {
    if (!a.has(i)) return fallback;
    const Value& v = a[i];
    bool ok = v.is_vector(3) || (allow2 && v.is_vector(2));
    if (!ok)
        arg_error(a, std::string(name) + " must be a vector of " + (allow2 ? "2 or 3" : "3") + " numbers, got " +
                         describe(v));
    const ValueList& l = v.as_list();
    glm::dvec3 out(l[0].as_number(), l[1].as_number(), l.size() > 2 ? l[2].as_number() : z2);
    if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z))
        arg_error(a, std::string(name) + " must be finite, got " + describe(v));
    return out;
}

// Users write sRGB display colours (docs/language.md §10); materials, lights
// and the background hold linear RGB, so every colour is converted here, once.
static glm::dvec4 to_linear(glm::dvec4 c) { return glm::dvec4(csg::srgb_to_linear(glm::dvec3(c)), c.a); }

glm::dvec4 arg_color(const Args& a, std::size_t i, const char* name) {
    const Value& v = a[i];
    glm::dvec4 c(0, 0, 0, 1);
    if (v.is_string()) {
        if (auto hex = parse_hex(v.as_string())) return to_linear(*hex);
        auto named = css_color(v.as_string());
        if (!named) arg_error(a, "unknown colour name " + to_repr(v));
        return to_linear(glm::dvec4(*named, 1.0));
    }
    if (!(v.is_vector(3) || v.is_vector(4)))
        arg_error(a, std::string(name) + " must be [r, g, b], [r, g, b, a] or a colour name, got " + describe(v));
    const ValueList& l = v.as_list();
    for (std::size_t k = 0; k < l.size(); ++k) {
        double x = l[k].as_number();
        if (!(x >= 0 && x <= 1)) arg_error(a, std::string(name) + " components must be in [0, 1], got " + describe(v));
        c[static_cast<int>(k)] = x;
    }
    return to_linear(c);
}

glm::dmat4 arg_matrix(const Args& a, std::size_t i, const char* name) {
    const Value& v = a[i];
    bool ok = v.is_list() && (v.as_list().size() == 3 || v.as_list().size() == 4);
    if (ok)
        for (const Value& row : v.as_list()) ok = ok && row.is_vector(4);
    if (!ok) arg_error(a, std::string(name) + " must be a 4x4 or 3x4 matrix of numbers");
    const ValueList& rows = v.as_list();
    glm::dmat4 m(1.0);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r)
        for (int col = 0; col < 4; ++col) {
            double x = rows[r].as_list()[col].as_number();
            if (!std::isfinite(x)) arg_error(a, std::string(name) + " must be finite");
            m[col][r] = x;
        }
    if (rows.size() == 4 && (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1))
        arg_error(a, "the last row must be [0, 0, 0, 1] (only affine transforms are supported)");
    return m;
}

}  // namespace kerf::eval
