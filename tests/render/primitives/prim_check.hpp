// Shared oracle checks for the primitive tests: a reported span list is
// compared with csg::contains / csg::surface_distance (membership.cpp, which
// never calls the ray code). The tolerance is the one documented in
// docs/accuracy.md:
//   |surface_distance(hit)| <= K · eps_T · (L + |o| + |t|·|d|)
// with L the largest parameter of the primitive, eps_T the precision of the
// solve. Membership is checked at every sample farther than that band from
// the surface (closer points cannot be decided at this precision).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "csg/membership.hpp"
#include "render/primitives/primitives.hpp"

namespace kerf::test {

using csg::Leaf;
using csg::PrimKind;
using glm::dvec3;

inline Leaf make_leaf(PrimKind kind, std::initializer_list<double> params) {
    Leaf leaf;
    leaf.kind = kind;
    int i = 0;
    for (double v : params) leaf.p[i++] = v;
    return leaf;
}

struct Ball {
    dvec3 centre;
    double radius;
};

// A ball around the solid (generous), used to aim rays and to bound sampling.
// Plane: a ball of radius `size` around the point of the plane nearest 0.
inline Ball bounding_ball(const Leaf& l, double size) {
    const double* p = l.p;
    switch (l.kind) {
        case PrimKind::Sphere: return {dvec3(0), p[0]};
        case PrimKind::Box: {
            const dvec3 lo(p[0], p[1], p[2]), hi(p[3], p[4], p[5]);
            return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo)};
        }
        case PrimKind::Cylinder:
            return {dvec3(0, 0, 0.5 * (p[0] + p[1])), std::hypot(0.5 * (p[1] - p[0]), std::max(p[2], p[3]))};
        case PrimKind::Torus: return {dvec3(0), p[0] + p[1]};
        case PrimKind::Plane: return {p[3] * dvec3(p[0], p[1], p[2]), size};
        case PrimKind::Paraboloid: return {dvec3(0, 0, 0.5 * p[0]), std::hypot(0.5 * p[0], p[1])};
        case PrimKind::Hyperboloid: return {dvec3(0), std::hypot(0.5 * p[0], std::max(p[1], p[2]))};
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: break;  // not generated here: their own tests
    }
    return {dvec3(0), size};
}

// L in the tolerance: the largest parameter magnitude (rounding the
// parameters to the solve's precision already moves the surface by eps·L).
inline double extent(const Leaf& l) {
    if (l.kind == PrimKind::Plane) return std::abs(l.p[3]);
    double m = 0;
    for (double v : l.p) m = std::max(m, std::abs(v));
    return m;
}

struct CheckStats {
    long rays = 0, hits = 0, crossings = 0, flips = 0, samples = 0, failures = 0;
    double max_units = 0;         // max over crossings of error / (eps_T · ref)
    std::vector<double> rel_err;  // error / size per crossing (for the accuracy table)
    std::string first_failure;
};

inline std::string describe(const Leaf& l, const dvec3& o, const dvec3& d) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "kind %d p {%.17g %.17g %.17g %.17g %.17g %.17g} o {%.17g %.17g %.17g} d {%.17g %.17g %.17g}",
                  int(l.kind), l.p[0], l.p[1], l.p[2], l.p[3], l.p[4], l.p[5], o.x, o.y, o.z, d.x, d.y, d.z);
    return buf;
}

// Checks one ray (o, d given in double, rounded to T for the solve; the
// rounded ray is the truth the oracle samples). K: tolerance factor.
template <typename T>
int check_ray(const Leaf& leaf, const dvec3& o, const dvec3& d, double K, double size, CheckStats& st,
              csg::Span<T>* spans_out = nullptr) {
    using V = glm::vec<3, T>;
    const V oT(o), dT(d);
    const dvec3 od(oT), dd(dT);
    csg::Span<T> s[csg::kMaxSpans];
    const int n = csg::intersect_leaf<T>(leaf, oT, dT, s);
    if (spans_out)
        for (int i = 0; i < n; ++i) spans_out[i] = s[i];
    ++st.rays;
    if (n > 0) ++st.hits;
    const double eps = std::numeric_limits<T>::epsilon();
    const double L = extent(leaf), olen = glm::length(od), dlen = glm::length(dd);
    auto ref = [&](double t) { return L + olen + (std::isfinite(t) ? std::abs(t) * dlen : 0.0); };
    auto band = [&](double t) { return K * eps * ref(t); };
    auto fail = [&](const std::string& what) {
        if (st.failures++ == 0) {
            st.first_failure = what + " | " + describe(leaf, od, dd) + " | spans";
            for (int i = 0; i < n; ++i) {
                char b[96];
                std::snprintf(b, sizeof b, " [%.17g %.17g]", double(s[i].t0), double(s[i].t1));
                st.first_failure += b;
            }
        }
    };
    if (n < 0 || n > csg::kMaxSpans) { fail("span count"); return n; }
    for (int i = 0; i < n; ++i) {
        if (!(s[i].t0 < s[i].t1)) fail("empty or unordered span");
        if (i > 0 && !(s[i - 1].t1 < s[i].t0)) fail("spans overlap or touch");
    }
    auto expected = [&](double t) {
        for (int i = 0; i < n; ++i)
            if (t > double(s[i].t0) && t < double(s[i].t1)) return true;
        return false;
    };
    // Membership at t, unless the point is within the tolerance band.
    auto check_at = [&](double t) {
        if (!std::isfinite(t)) return false;
        const dvec3 x = od + t * dd;
        if (std::abs(csg::surface_distance(leaf, x)) <= band(t)) return false;
        ++st.samples;
        if (csg::contains(leaf, x) != expected(t)) {
            char b[96];
            std::snprintf(b, sizeof b, "membership wrong at t=%.17g", t);
            fail(b);
        }
        return true;
    };
    std::vector<double> ends;
    for (int i = 0; i < n; ++i) {
        ends.push_back(double(s[i].t0));
        ends.push_back(double(s[i].t1));
    }
    for (double t : ends) {
        if (!std::isfinite(t)) continue;
        ++st.crossings;
        const dvec3 x = od + t * dd;
        const double err = std::abs(csg::surface_distance(leaf, x));
        st.max_units = std::max(st.max_units, err / (eps * ref(t)));
        st.rel_err.push_back(err / size);
        if (!(err <= band(t))) {
            char b[128];
            std::snprintf(b, sizeof b, "crossing t=%.17g off the surface by %.3g (band %.3g)", t, err, band(t));
            fail(b);
        }
        // The flip: membership just before and just after the crossing.
        for (double m = 2; m < 1e7; m *= 8) {
            const double dt = m * band(t) / dlen;
            const bool a = check_at(t - dt), b = check_at(t + dt);
            if (a && b) { ++st.flips; break; }
        }
    }
    // Constant membership between crossings: dense samples over the region
    // around the solid, plus the middle of every span and gap.
    const Ball ball = bounding_ball(leaf, size);
    const dvec3 oc = od - ball.centre;
    const double a = glm::dot(dd, dd), hb = glm::dot(oc, dd);
    const double c = glm::dot(oc, oc) - 1.5625 * ball.radius * ball.radius;
    const double disc = hb * hb - a * c;
    if (disc > 0) {
        const double ta = (-hb - std::sqrt(disc)) / a, tb = (-hb + std::sqrt(disc)) / a;
        constexpr int kDense = 24;
        for (int j = 0; j < kDense; ++j) check_at(ta + (tb - ta) * (j + 0.5) / kDense);
    }
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const double lo = i == 0 ? ends[0] - std::max(1.0, std::abs(ends[0])) : ends[i - 1];
        if (std::isfinite(lo) && std::isfinite(ends[i])) check_at(0.5 * (lo + ends[i]));
    }
    if (!ends.empty() && std::isfinite(ends.back())) check_at(ends.back() + std::max(1.0, std::abs(ends.back())));
    return n;
}

// Random rays, seeded: a uniform direction through a point near the solid,
// starting anywhere from inside it to `far` sizes away; |d| spans 1e-3..1e3.
struct RayGen {
    std::mt19937_64 rng;
    explicit RayGen(std::uint64_t seed) : rng(seed) {}
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    dvec3 unit() {
        for (;;) {
            const dvec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l2 = glm::dot(v, v);
            if (l2 > 1e-4 && l2 <= 1) return v / std::sqrt(l2);
        }
    }
    // `distance`: how far back from the aim point the origin starts (absolute).
    void ray(const Ball& ball, double distance, dvec3& o, dvec3& d) {
        const dvec3 aim = ball.centre + 1.1 * ball.radius * unit() * std::cbrt(uniform(0, 1));
        const dvec3 u = unit();
        o = aim - distance * u;
        d = u * std::pow(10.0, uniform(-3, 3));
    }
};

inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// Prints one accuracy row when KERF_ACCURACY_REPORT is set, as CSV:
// shape,precision,ray set,scale,crossings,max err/size,median err/size,max units
// (bench/accuracy_table.py turns these into the table of docs/accuracy.md).
inline void report(const char* prim, const char* precision, const char* rays, double scale, const CheckStats& st) {
    if (!std::getenv("KERF_ACCURACY_REPORT")) return;
    const double mx = st.rel_err.empty() ? 0 : *std::max_element(st.rel_err.begin(), st.rel_err.end());
    std::printf("ACC,%s,%s,%s,%.0e,%ld,%.2e,%.2e,%.2f\n", prim, precision, rays, scale, st.crossings, mx,
                median(st.rel_err), st.max_units);
}

// The standard random suite for one shape family: for every scale 1e-6..1e6
// and both precisions, `near` rays starting within a few sizes, and `far`
// rays starting 1e6 (absolute: a far translation) and 1e6 sizes away. Every
// check must pass with tolerance factor K (float: Kf).
template <typename MakeLeaf>
void random_suite(const char* name, MakeLeaf make, double K, double Kf, int near, int far, std::uint64_t seed) {
    RayGen gen(seed);
    for (int e = -6; e <= 6; ++e) {
        const double scale = std::pow(10.0, e);
        const Leaf leaf = make(scale);
        const Ball ball = bounding_ball(leaf, scale);
        CheckStats nd, nf, ad, af, rd, rf;  // near; 1e6 away (absolute); 1e6 sizes away
        for (int i = 0; i < near; ++i) {
            dvec3 o, d;
            gen.ray(ball, ball.radius * gen.uniform(0, 3), o, d);
            check_ray<double>(leaf, o, d, K, scale, nd);
            check_ray<float>(leaf, o, d, Kf, scale, nf);
        }
        for (int i = 0; i < far; ++i) {
            dvec3 o, d;
            gen.ray(ball, i % 2 ? 1e6 : 1e6 * scale, o, d);
            check_ray<double>(leaf, o, d, K, scale, i % 2 ? ad : rd);
            check_ray<float>(leaf, o, d, Kf, scale, i % 2 ? af : rf);
        }
        for (const CheckStats* st : {&nd, &nf, &ad, &af, &rd, &rf}) {
            INFO(name << " scale " << scale << ": " << st->first_failure);
            CHECK(st->failures == 0);
        }
        // Not vacuous: most near crossings had their flip checked.
        CHECK(nd.flips > nd.crossings * 9 / 10);
        CHECK(nd.hits > 0);  // thin shapes (1e-3 tori) are rarely hit by chance: aimed tests cover them
        report(name, "double", "near", scale, nd);
        report(name, "float", "near", scale, nf);
        report(name, "double", "far-abs", scale, ad);
        report(name, "float", "far-abs", scale, af);
        report(name, "double", "far-rel", scale, rd);
        report(name, "float", "far-rel", scale, rf);
    }
}

}  // namespace kerf::test

namespace kerf::test {

struct Expected {
    double t0, t1;
};

// Compares spans with a closed-form answer: same count, every end within
// `tol` (absolute, in t). Returns a message, empty when they agree.
template <typename T>
std::string compare_spans(const Leaf& leaf, const dvec3& o, const dvec3& d, std::initializer_list<Expected> want,
                          double tol) {
    using V = glm::vec<3, T>;
    csg::Span<T> s[csg::kMaxSpans];
    const int n = csg::intersect_leaf<T>(leaf, V(o), V(d), s);
    std::string got;
    for (int i = 0; i < n; ++i) {
        char b[96];
        std::snprintf(b, sizeof b, " [%.17g %.17g]", double(s[i].t0), double(s[i].t1));
        got += b;
    }
    bool ok = n == int(want.size());
    int i = 0;
    for (const Expected& e : want) {
        if (!ok) break;
        auto close = [&](double a, double b) { return a == b || std::abs(a - b) <= tol; };
        ok = close(double(s[i].t0), e.t0) && close(double(s[i].t1), e.t1);
        ++i;
    }
    if (ok) return "";
    std::string w;
    for (const Expected& e : want) {
        char b[96];
        std::snprintf(b, sizeof b, " [%.17g %.17g]", e.t0, e.t1);
        w += b;
    }
    return "got" + got + " want" + w + " | " + describe(leaf, o, d);
}

}  // namespace kerf::test

namespace kerf::test {

// A point of the surface from the solid's own parametrisation (not from the
// ray code): uniform enough to reach every part (sides, caps, faces).
inline dvec3 surface_point(const Leaf& l, RayGen& g) {
    const double* p = l.p;
    const double phi = g.uniform(0, 6.283185307179586);
    const dvec3 radial(std::cos(phi), std::sin(phi), 0);
    switch (l.kind) {
        case PrimKind::Sphere: return p[0] * g.unit();
        case PrimKind::Box: {
            const int face = int(g.uniform(0, 6)) % 6, axis = face % 3;
            dvec3 x(g.uniform(p[0], p[3]), g.uniform(p[1], p[4]), g.uniform(p[2], p[5]));
            x[axis] = face < 3 ? p[axis] : p[axis + 3];
            return x;
        }
        case PrimKind::Cylinder: {
            const double pick = g.uniform(0, 1);
            if (pick < 0.2) return radial * p[2] * std::sqrt(g.uniform(0, 1)) + dvec3(0, 0, p[0]);
            if (pick < 0.4) return radial * p[3] * std::sqrt(g.uniform(0, 1)) + dvec3(0, 0, p[1]);
            const double z = g.uniform(p[0], p[1]);
            return radial * (p[2] + (p[3] - p[2]) * (z - p[0]) / (p[1] - p[0])) + dvec3(0, 0, z);
        }
        case PrimKind::Torus: {
            const double v = g.uniform(0, 6.283185307179586);
            return radial * (p[0] + p[1] * std::cos(v)) + dvec3(0, 0, p[1] * std::sin(v));
        }
        case PrimKind::Plane: {
            const dvec3 n(p[0], p[1], p[2]);
            const dvec3 t1 = glm::normalize(glm::cross(n, g.unit())), t2 = glm::cross(n, t1);
            return p[3] * n + g.uniform(-1, 1) * t1 + g.uniform(-1, 1) * t2;
        }
        case PrimKind::Paraboloid: {
            const double rho = p[1] * std::sqrt(g.uniform(0, 1));
            if (g.uniform(0, 1) < 0.3) return radial * rho + dvec3(0, 0, p[0]);
            return radial * rho + dvec3(0, 0, p[0] * rho * rho / (p[1] * p[1]));
        }
        case PrimKind::Hyperboloid: {
            const double half = 0.5 * p[0], pick = g.uniform(0, 1);
            if (pick < 0.3) return radial * p[1] * std::sqrt(g.uniform(0, 1)) + dvec3(0, 0, pick < 0.15 ? -half : half);
            const double z = g.uniform(-half, half), s = z / half;
            return radial * std::sqrt(p[2] * p[2] + (p[1] * p[1] - p[2] * p[2]) * s * s) + dvec3(0, 0, z);
        }
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: break;  // not generated here: their own tests
    }
    return dvec3(0);
}

// Poles, edges, corners, rims, apexes: where the surface is singular or a
// ray is most likely to meet two parts at once.
inline std::vector<dvec3> special_points(const Leaf& l) {
    const double* p = l.p;
    std::vector<dvec3> v;
    switch (l.kind) {
        case PrimKind::Sphere:
            for (int a = 0; a < 3; ++a)
                for (double sgn : {-1.0, 1.0}) {
                    dvec3 x(0);
                    x[a] = sgn * p[0];
                    v.push_back(x);
                }
            break;
        case PrimKind::Box:
            for (int c = 0; c < 8; ++c)  // corners
                v.push_back({c & 1 ? p[3] : p[0], c & 2 ? p[4] : p[1], c & 4 ? p[5] : p[2]});
            for (int a = 0; a < 3; ++a)  // edge midpoints
                for (int c = 0; c < 4; ++c) {
                    dvec3 x;
                    const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
                    x[a] = 0.5 * (p[a] + p[a + 3]);
                    x[b1] = c & 1 ? p[b1 + 3] : p[b1];
                    x[b2] = c & 2 ? p[b2 + 3] : p[b2];
                    v.push_back(x);
                }
            break;
        case PrimKind::Cylinder:
            for (double a = 0; a < 6.28; a += 1.5707963267948966) {
                v.push_back({p[2] * std::cos(a), p[2] * std::sin(a), p[0]});  // rims (or the apex)
                v.push_back({p[3] * std::cos(a), p[3] * std::sin(a), p[1]});
            }
            v.push_back({0, 0, p[0]});
            v.push_back({0, 0, p[1]});
            break;
        case PrimKind::Torus:
            for (double a = 0; a < 6.28; a += 1.5707963267948966) {
                const dvec3 r(std::cos(a), std::sin(a), 0);
                v.push_back(r * (p[0] - p[1]));
                v.push_back(r * (p[0] + p[1]));
                v.push_back(r * p[0] + dvec3(0, 0, p[1]));
                v.push_back(r * p[0] - dvec3(0, 0, p[1]));
            }
            break;
        case PrimKind::Plane: v.push_back(p[3] * dvec3(p[0], p[1], p[2])); break;
        case PrimKind::Paraboloid:
            v.push_back({0, 0, 0});
            v.push_back({0, 0, p[0]});
            for (double a = 0; a < 6.28; a += 1.5707963267948966) v.push_back({p[1] * std::cos(a), p[1] * std::sin(a), p[0]});
            break;
        case PrimKind::Hyperboloid:
            for (double a = 0; a < 6.28; a += 1.5707963267948966) {
                const dvec3 r(std::cos(a), std::sin(a), 0);
                v.push_back(r * p[1] + dvec3(0, 0, 0.5 * p[0]));
                v.push_back(r * p[1] - dvec3(0, 0, 0.5 * p[0]));
                v.push_back(r * p[2]);
            }
            v.push_back({0, 0, 0.5 * p[0]});
            v.push_back({0, 0, -0.5 * p[0]});
            break;
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: break;  // their own tests (test_mesh_leaves, test_prism, test_lathe)
    }
    return v;
}

// One leaf per shape family at scale s (the families of the random suites).
inline std::vector<std::pair<const char*, Leaf>> all_shapes(double s) {
    return {
        {"sphere", make_leaf(PrimKind::Sphere, {s})},
        {"box", make_leaf(PrimKind::Box, {-0.3 * s, -0.6 * s, -0.2 * s, 0.7 * s, 0.4 * s, 0.9 * s})},
        {"cylinder", make_leaf(PrimKind::Cylinder, {-0.5 * s, 0.7 * s, 0.6 * s, 0.6 * s})},
        {"frustum", make_leaf(PrimKind::Cylinder, {-0.5 * s, 0.7 * s, 0.6 * s, 0.3 * s})},
        {"cone", make_leaf(PrimKind::Cylinder, {0, s, 0.5 * s, 0})},
        {"torus", make_leaf(PrimKind::Torus, {s, 0.25 * s})},
        {"thin torus", make_leaf(PrimKind::Torus, {s, 1e-3 * s})},
        {"plane", make_leaf(PrimKind::Plane, {0.6, 0, 0.8, 0.2 * s})},
        {"paraboloid", make_leaf(PrimKind::Paraboloid, {s, 0.7 * s})},
        {"hyperboloid", make_leaf(PrimKind::Hyperboloid, {s, 0.6 * s, 0.3 * s})},
        {"double cone", make_leaf(PrimKind::Hyperboloid, {s, 0.6 * s, 0})},
    };
}

}  // namespace kerf::test
