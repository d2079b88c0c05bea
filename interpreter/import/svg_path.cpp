// SVG attribute languages (svg_path.hpp): path data after the SVG 1.1
// grammar (numbers run together as "1.5.5" or "1-2", arc flags without
// separators), arcs converted from endpoint to centre form (SVG 1.1 F.6.5).
#include "interpreter/import/svg_path.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include <clipper.hpp>

#include "interpreter/text/layout.hpp"

namespace kerf::eval::svg {

namespace {

constexpr double kPi = std::numbers::pi;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

// A cursor over an attribute value, its errors naming the character.
class Reader {
public:
    explicit Reader(std::string_view s) : s_(s) {}

    void skip_separators() {
        while (i_ < s_.size() && (is_space(s_[i_]) || s_[i_] == ',')) ++i_;
    }
    void skip_spaces() {
        while (i_ < s_.size() && is_space(s_[i_])) ++i_;
    }
    bool at_end() const { return i_ >= s_.size(); }
    char peek() const { return at_end() ? '\0' : s_[i_]; }
    char take() { return s_[i_++]; }
    bool number_next() {
        skip_separators();
        const char c = peek();
        return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
    }
    // sign? (digits ('.' digits?)? | '.' digits) ([eE] sign? digits)?
    double number() {
        skip_separators();
        const std::size_t start = i_;
        std::size_t j = i_;
        if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
        const std::size_t int_start = j;
        while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
        bool digits = j > int_start;
        if (j < s_.size() && s_[j] == '.') {
            const std::size_t f = ++j;
            while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
            digits |= j > f;
        }
        if (!digits) fail(start, "a number");
        if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
            std::size_t k = j + 1;
            if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
            const std::size_t e = k;
            while (k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]))) ++k;
            if (k > e) j = k;  // else "e" starts something else (an "em" unit)
        }
        const std::string text(s_.substr(start, j - start));
        const double v = std::strtod(text.c_str(), nullptr);
        if (!std::isfinite(v)) fail(start, "a finite number");
        i_ = j;
        return v;
    }
    bool flag() {
        skip_separators();
        if (peek() != '0' && peek() != '1') fail(i_, "an arc flag 0 or 1");
        return take() == '1';
    }
    [[noreturn]] void fail(std::size_t at, const std::string& expected) const {
        const std::string got = at < s_.size() ? "'" + std::string(1, s_[at]) + "'" : "the end";
        throw DataError("expected " + expected + " at character " + std::to_string(at + 1) + ", got " + got);
    }
    std::size_t pos() const { return i_; }
    std::string_view rest() const { return s_.substr(std::min(i_, s_.size())); }

private:
    std::string_view s_;
    std::size_t i_ = 0;
};

double extent(std::initializer_list<glm::dvec2> pts) {
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (glm::dvec2 p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return glm::length(hi - lo);
}

// Chord count for an absolute tolerance that is relative to the curve's
// size; a degenerate curve (all control points equal) is one chord.
double curve_tol(double size, double tolerance) { return size > 0 ? tolerance * size : 1; }

void cubic(Chain& out, glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 p3, double tolerance) {
    const int n = text::cubic_chords(p0, p1, p2, p3, curve_tol(extent({p0, p1, p2, p3}), tolerance));
    for (int i = 1; i <= n; ++i) {
        const double t = double(i) / n, u = 1 - t;
        out.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
    }
}

void quadratic(Chain& out, glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, double tolerance) {
    const int n = text::quadratic_chords(p0, p1, p2, curve_tol(extent({p0, p1, p2}), tolerance));
    for (int i = 1; i <= n; ++i) {
        const double t = double(i) / n, u = 1 - t;
        out.push_back(u * u * p0 + 2 * u * t * p1 + t * t * p2);
    }
}

// The elliptical arc from p to q (SVG 1.1 F.6.5, radii scaled up when too
// small), flattened; a zero radius is the straight line.
void arc(Chain& out, glm::dvec2 p, glm::dvec2 q, double rx, double ry, double phi_deg, bool large, bool sweep,
         double tolerance) {
    if (p == q) return;
    rx = std::abs(rx), ry = std::abs(ry);
    if (rx == 0 || ry == 0) return out.push_back(q);
    const double phi = phi_deg * kPi / 180, c = std::cos(phi), s = std::sin(phi);
    const glm::dvec2 h = (p - q) / 2.0;
    const glm::dvec2 p1(c * h.x + s * h.y, -s * h.x + c * h.y);
    const double lambda = p1.x * p1.x / (rx * rx) + p1.y * p1.y / (ry * ry);
    if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
    const double num = rx * rx * ry * ry - rx * rx * p1.y * p1.y - ry * ry * p1.x * p1.x;
    const double den = rx * rx * p1.y * p1.y + ry * ry * p1.x * p1.x;
    double k = std::sqrt(std::max(0.0, num / den));
    if (large == sweep) k = -k;
    const glm::dvec2 c1(k * rx * p1.y / ry, -k * ry * p1.x / rx);
    const glm::dvec2 centre = glm::dvec2(c * c1.x - s * c1.y, s * c1.x + c * c1.y) + (p + q) / 2.0;
    auto angle = [](glm::dvec2 u, glm::dvec2 v) {
        return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
    };
    const glm::dvec2 u((p1.x - c1.x) / rx, (p1.y - c1.y) / ry), v((-p1.x - c1.x) / rx, (-p1.y - c1.y) / ry);
    const double t1 = angle({1, 0}, u);
    double dt = angle(u, v);
    if (!sweep && dt > 0) dt -= 2 * kPi;
    if (sweep && dt < 0) dt += 2 * kPi;
    const int n = std::max(1, int(std::ceil(circle_segments(tolerance) * std::abs(dt) / (2 * kPi))));
    for (int i = 1; i < n; ++i) {
        const double t = t1 + dt * i / n;
        const glm::dvec2 e(rx * std::cos(t), ry * std::sin(t));
        out.push_back(centre + glm::dvec2(c * e.x - s * e.y, s * e.x + c * e.y));
    }
    out.push_back(q);  // exactly the end point, so a closing arc meets its start
}

}  // namespace

std::vector<Subpath> parse_path(std::string_view d, double tolerance, std::uint64_t max_points) {
    std::uint64_t points = 0;  // in the subpaths before the last
    Reader r(d);
    std::vector<Subpath> out;
    glm::dvec2 cur(0), start(0), ctrl(0);  // ctrl: the last control point, for S and T
    char cmd = 0, last = 0;
    auto finish = [&] {
        if (!out.empty() && !out.back().closed) {
            Chain& c = out.back().points;
            if (c.size() >= 3 && c.front() == c.back()) c.pop_back(), out.back().closed = true;
        }
    };
    auto begin = [&](glm::dvec2 p) {
        finish();
        if (!out.empty()) points += out.back().points.size();
        out.push_back({{p}, false});
    };
    r.skip_separators();
    while (!r.at_end()) {
        const char c = r.peek();
        if (std::isalpha(static_cast<unsigned char>(c))) {
            if (!std::strchr("MmLlHhVvCcSsQqTtAaZz", c)) r.fail(r.pos(), "a path command");
            cmd = r.take();
        } else if (cmd == 0) {
            r.fail(r.pos(), "a moveto (M or m)");
        } else if (cmd == 'Z' || cmd == 'z') {
            r.fail(r.pos(), "a path command after Z");
        }
        const bool rel = std::islower(static_cast<unsigned char>(cmd));
        const glm::dvec2 base = rel ? cur : glm::dvec2(0);
        auto point = [&] {
            const double x = r.number();
            return base + glm::dvec2(x, r.number());
        };
        if (cmd != 'M' && cmd != 'm' && out.empty()) r.fail(r.pos() - 1, "a moveto (M or m)");
        if (out.size() && out.back().closed && cmd != 'M' && cmd != 'm' && cmd != 'Z' && cmd != 'z')
            begin(start);  // drawing on after Z starts at the closed subpath's start
        glm::dvec2 next_ctrl(0);
        bool curve = false;
        switch (std::toupper(static_cast<unsigned char>(cmd))) {
        case 'M':
            cur = start = point();
            begin(cur);
            cmd = rel ? 'l' : 'L';  // further pairs are lines
            break;
        case 'L': cur = point(); out.back().points.push_back(cur); break;
        case 'H': cur.x = base.x + r.number(); out.back().points.push_back(cur); break;
        case 'V': cur.y = (rel ? cur.y : 0) + r.number(); out.back().points.push_back(cur); break;
        case 'C': case 'S': {
            const bool smooth = std::toupper(static_cast<unsigned char>(cmd)) == 'S';
            const glm::dvec2 p1 = smooth ? (last == 'C' || last == 'S' ? 2.0 * cur - ctrl : cur) : point();
            const glm::dvec2 p2 = point(), p3 = point();
            cubic(out.back().points, cur, p1, p2, p3, tolerance);
            next_ctrl = p2, curve = true, cur = p3;
            break;
        }
        case 'Q': case 'T': {
            const bool smooth = std::toupper(static_cast<unsigned char>(cmd)) == 'T';
            const glm::dvec2 p1 = smooth ? (last == 'Q' || last == 'T' ? 2.0 * cur - ctrl : cur) : point();
            const glm::dvec2 p2 = point();
            quadratic(out.back().points, cur, p1, p2, tolerance);
            next_ctrl = p1, curve = true, cur = p2;
            break;
        }
        case 'A': {
            const double rx = r.number(), ry = r.number(), phi = r.number();
            const bool large = r.flag(), sweep = r.flag();
            const glm::dvec2 q = point();
            arc(out.back().points, cur, q, rx, ry, phi, large, sweep, tolerance);
            cur = q;
            break;
        }
        case 'Z':
            out.back().closed = true;
            if (out.back().points.size() > 1 && out.back().points.back() == out.back().points.front())
                out.back().points.pop_back();
            cur = start;
            break;
        }
        if (max_points && !out.empty() && points + out.back().points.size() > max_points)
            throw DataError("more than " + std::to_string(max_points) + " points once its curves are flattened");
        last = curve ? char(std::toupper(static_cast<unsigned char>(cmd))) : 0;
        ctrl = next_ctrl;
        r.skip_separators();
    }
    finish();
    return out;
}

Chain parse_points(std::string_view s) {
    Reader r(s);
    Chain out;
    while (r.number_next()) {
        const double x = r.number();
        if (!r.number_next()) break;
        out.emplace_back(x, r.number());
    }
    r.skip_separators();
    if (!r.at_end()) r.fail(r.pos(), "a number");
    return out;
}

Map2 parse_transform(std::string_view s) {
    Reader r(s);
    Map2 m(1.0);
    r.skip_separators();
    while (!r.at_end()) {
        const std::size_t at = r.pos();
        std::string name;
        while (std::isalpha(static_cast<unsigned char>(r.peek()))) name += r.take();
        r.skip_spaces();
        if (name.empty() || r.peek() != '(') r.fail(at, "a transform (matrix, translate, scale, rotate, skewX, skewY)");
        r.take();
        std::vector<double> a;
        while (r.number_next()) a.push_back(r.number());
        r.skip_separators();
        if (r.peek() != ')') r.fail(r.pos(), "')'");
        r.take();
        auto arity = [&](std::initializer_list<std::size_t> ok) {
            if (std::find(ok.begin(), ok.end(), a.size()) == ok.end())
                throw DataError(name + "() at character " + std::to_string(at + 1) + " takes " +
                                (ok.size() == 1 ? std::to_string(*ok.begin())
                                                : std::to_string(*ok.begin()) + " or " + std::to_string(*(ok.end() - 1))) +
                                " numbers, got " + std::to_string(a.size()));
        };
        Map2 t(1.0);
        const double deg = kPi / 180;
        if (name == "matrix") {
            arity({6});
            t[0] = {a[0], a[1], 0}, t[1] = {a[2], a[3], 0}, t[2] = {a[4], a[5], 1};
        } else if (name == "translate") {
            arity({1, 2});
            t[2] = {a[0], a.size() > 1 ? a[1] : 0, 1};
        } else if (name == "scale") {
            arity({1, 2});
            t[0][0] = a[0], t[1][1] = a.size() > 1 ? a[1] : a[0];
        } else if (name == "rotate") {
            arity({1, 3});
            const double c = std::cos(a[0] * deg), sn = std::sin(a[0] * deg);
            const glm::dvec2 o = a.size() == 3 ? glm::dvec2(a[1], a[2]) : glm::dvec2(0);
            t[0] = {c, sn, 0}, t[1] = {-sn, c, 0};
            t[2] = glm::dvec3(o - glm::dvec2(c * o.x - sn * o.y, sn * o.x + c * o.y), 1);
        } else if (name == "skewX") {
            arity({1});
            t[1][0] = std::tan(a[0] * deg);
        } else if (name == "skewY") {
            arity({1});
            t[0][1] = std::tan(a[0] * deg);
        } else {
            r.fail(at, "a transform (matrix, translate, scale, rotate, skewX, skewY)");
        }
        m = m * t;
        r.skip_separators();
    }
    return m;
}

double parse_number_prefix(std::string_view s, std::string_view& rest) {
    Reader r(s);
    r.skip_spaces();
    const double v = r.number();
    r.skip_spaces();
    rest = r.rest();
    while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
    return v;
}

std::vector<Chain> stroke_outline(const std::vector<Chain>& open, const Stroke& stroke, double tolerance) {
    using namespace ClipperLib;
    if (!(stroke.width > 0)) return {};
    if (!std::isfinite(stroke.width)) throw DataError("a stroke too wide to draw");
    double size = stroke.width;
    for (const Chain& c : open)
        for (glm::dvec2 p : c) size = std::max({size, std::abs(p.x), std::abs(p.y)});
    if (!std::isfinite(size + stroke.width)) throw DataError("coordinates too large to stroke");
    // Integer grid of 2^-50 of the extent, as region2d.hpp's.
    const double scale = std::ldexp(1.0, 50 - std::ilogb(size + stroke.width) - 1);
    const double delta = stroke.width / 2 * scale;
    ClipperOffset off(std::max(stroke.miter_limit, 1.0), std::max(tolerance * delta, 0.25));
    const JoinType join = stroke.join == Stroke::Miter ? jtMiter : stroke.join == Stroke::RoundJoin ? jtRound : jtSquare;
    const EndType end = stroke.cap == Stroke::Butt ? etOpenButt : stroke.cap == Stroke::Round ? etOpenRound : etOpenSquare;
    for (const Chain& c : open) {
        Path p;
        for (glm::dvec2 q : c) p.push_back({cInt(std::llround(q.x * scale)), cInt(std::llround(q.y * scale))});
        off.AddPath(p, join, end);
    }
    Paths result;
    off.Execute(result, delta);
    std::vector<Chain> out;
    for (const Path& p : result) {
        Chain c;
        for (const IntPoint& q : p) c.emplace_back(double(q.X) / scale, double(q.Y) / scale);
        if (c.size() >= 3) out.push_back(std::move(c));
    }
    return out;
}

}  // namespace kerf::eval::svg
