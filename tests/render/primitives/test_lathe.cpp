// The lathe leaf against the even-odd oracle (csg::contains_lathe: the point
// turned back into the (ρ, z) half-plane, then a textbook point-in-polygon
// that shares no code with the ray test): random profiles — stars away from
// the axis with holes, self-intersecting scribbles, profiles along the axis
// with horizontal, vertical and collinear edges, zero-area profiles,
// overlapping copies — and random rays, many through vertex circles, along
// the axis, parallel to the caps, through the axis or grazing, at scales
// 1e-6 … 1e6 and far from the origin. At every sample along the ray
// farther than the tolerance band from the surface, membership must equal
// "inside a reported span", and every reported end must lie on the surface.
// The distance to a surface of revolution is the distance in the meridian
// half-plane, so the band is exact.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "csg/membership.hpp"
#include "tests/render/primitives/polygon_sections.hpp"
#include "render/primitives/lathe.hpp"

using namespace kerf;
using test::add_path;
using test::finish;
using test::Section;
using test::seg_distance;
using test::star;
using glm::dvec2;
using glm::dvec3;

namespace {

// Sections in x >= 0 (x = radius), about unit size, scaled by `scale`.
Section make_profile(std::mt19937_64& rng, int kind, double scale) {
    std::uniform_real_distribution<double> u(0, 1);
    Section s;
    if (kind == 0) {  // a star ring with two holes
        add_path(s, star(rng, {1.2, 0}, 1, 12));
        add_path(s, star(rng, {1.35, 0.1}, 0.2, 5));
        add_path(s, star(rng, {1.05, -0.1}, 0.15, 4));
    } else if (kind == 1) {  // self-intersecting scribble
        std::vector<dvec2> p;
        for (int i = 0; i < 9; ++i) p.push_back({2 * u(rng), 2 * u(rng) - 1});
        add_path(s, p);
    } else if (kind == 2) {  // on the axis: collinear, horizontal and vertical edges, a square hole
        add_path(s, {{0, -1}, {1, -1}, {2, -1}, {2, 0}, {2, 1}, {1, 1}, {0, 1}, {0, 0}});
        add_path(s, {{0.5, -0.5}, {1, -0.5}, {1.5, -0.5}, {1.5, 0.5}, {0.5, 0.5}});
    } else if (kind == 3) {  // zero area: one line, and a back-and-forth path
        add_path(s, {{0.2, -0.5}, {1, 0}, {1.8, 0.5}});
        add_path(s, {{0, 1}, {2, 1}});
    } else if (kind == 4) {  // overlapping copies: even-odd makes the overlap a hole
        add_path(s, {{0, -1}, {1.5, -1}, {1.5, 0.5}, {0, 0.5}});
        add_path(s, {{0.5, -0.5}, {2, -0.5}, {2, 1}, {0.5, 1}});
    } else {  // a cone to a point on the axis and a spindle (vertices on the axis)
        add_path(s, {{0, 1}, {1, -1}, {0, -1}});
        add_path(s, {{0, 1.2}, {0.4, 1.6}, {0, 2}});
    }
    for (glm::dvec4& e : s.poly.edges) e *= scale;
    for (dvec2& v : s.vertices) v *= scale;
    finish(s);
    return s;
}

double surface_gap(const Section& s, const dvec3& p) {
    const dvec2 m(std::hypot(p.x, p.y), p.z);
    double best = 1e300;
    for (const glm::dvec4& e : s.poly.edges) best = std::min(best, seg_distance(e, m));
    return best;
}

template <typename T>
int spans_of(const Section& s, const dvec3& o, const dvec3& d, std::vector<csg::PrismSpan<T>>& out) {
    out.resize(csg::lathe_span_room(s.poly.edges.size()));
    std::vector<csg::PrismCrossing<T>> scratch(csg::lathe_crossing_room(s.poly.edges.size()));
    return csg::intersect_lathe<T>(s.poly, glm::vec<3, T>(o), glm::vec<3, T>(d), out.data(), scratch.data());
}

// `shift`: the whole setup moved along the axis and the rays' origins away
// from it (a far camera), in units of scale.
template <typename T>
void check_rays(const Section& s, double scale, std::mt19937_64& rng, int rays, double far = 3) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<csg::PrismSpan<T>> out;
    const double tol_k = std::is_same_v<T, float> ? 3e-5 : 1e-11;
    for (int r = 0; r < rays; ++r) {
        dvec3 o(u(rng), u(rng), u(rng));
        o = far * scale * o / glm::length(o);
        dvec3 target(2 * u(rng) * scale, 2 * u(rng) * scale, u(rng) * scale);
        const int mode = r % 6;
        if (mode == 1) {  // through a vertex circle
            const dvec2 v = s.vertices[std::size_t(rng() % s.vertices.size())];
            const double a = M_PI * u(rng);
            target = dvec3(v.x * std::cos(a), v.x * std::sin(a), v.y);
        } else if (mode == 2) {  // parallel to the caps, at a vertex's height half the time
            target.z = o.z = r % 12 == 2 ? s.vertices[std::size_t(rng() % s.vertices.size())].y : u(rng) * scale;
        } else if (mode == 3) {  // parallel to the axis
            o = dvec3(target.x, target.y, far * scale);
        } else if (mode == 4) {  // through the axis
            target.x = target.y = 0;
        } else if (mode == 5) {  // along the axis
            o = dvec3(0, 0, far * scale);
            target = dvec3(0, 0, 0);
        }
        const dvec3 d = (target - o) * (0.5 + std::abs(u(rng)));
        const int n = spans_of<T>(s, o, d, out);
        REQUIRE(n <= int(out.size()));
        const double tol = tol_k * 4 * far * scale;
        // A ray through a cone's apex on the axis meets it in a double root,
        // found to √ε only (as a tangent ray): ends that close to an apex
        // get that band (docs/accuracy.md).
        const double apex_tol = 30 * std::sqrt(std::numeric_limits<T>::epsilon()) * far * scale;
        auto near_apex = [&](const dvec3& p) {
            for (const dvec2& v : s.vertices)
                if (v.x == 0 && glm::length(p - dvec3(0, 0, v.y)) <= apex_tol) return true;
            return false;
        };
        std::vector<double> ends;
        for (int i = 0; i < n; ++i) {
            INFO("span " << i << " of " << n << ": " << out[i].s.t0 << " .. " << out[i].s.t1 << " ray " << r << " mode "
                          << mode);
            REQUIRE(out[i].s.t0 < out[i].s.t1);
            if (i > 0) REQUIRE(out[i - 1].s.t1 < out[i].s.t0);
            for (double t : {double(out[i].s.t0), double(out[i].s.t1)}) {
                ends.push_back(t);
                CHECK(surface_gap(s, o + t * d) <= (near_apex(o + t * d) ? apex_tol : tol));
            }
        }
        const double tlen = glm::length(d);
        for (int k = 0; k <= 300; ++k) {
            const double t = -1.0 + 3.0 * k / 300.0;
            const dvec3 p = o + t * d;
            if (surface_gap(s, p) <= 4 * tol || near_apex(p)) continue;
            bool near_end = false;
            for (double e : ends) near_end = near_end || std::abs(e - t) * tlen <= 4 * tol;
            if (near_end) continue;
            bool in_span = false;
            for (int i = 0; i < n; ++i) in_span = in_span || (out[i].s.t0 < t && t < out[i].s.t1);
            INFO("ray " << r << " mode " << mode << " t " << t << " n " << n << " o " << o.x << " " << o.y << " " << o.z
                        << " d " << d.x << " " << d.y << " " << d.z << " gap " << surface_gap(s, p));
            REQUIRE(in_span == csg::contains_lathe(s.poly, p));
        }
    }
}

// The volume by chords of a grid of rays along z over [-w, w]²: exact per
// ray, so only the 2D midpoint quadrature errs.
double grid_volume(const Section& s, double w, int n) {
    std::vector<csg::PrismSpan<double>> out;
    double v = 0;
    const double h = 2 * w / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const dvec3 o(-w + (i + 0.5) * h, -w + (j + 0.5) * h, -10 * w);
            const int k = spans_of<double>(s, o, {0, 0, 1}, out);
            for (int q = 0; q < k; ++q) v += (out[q].s.t1 - out[q].s.t0) * h * h;
        }
    return v;
}

}  // namespace

TEMPLATE_TEST_CASE("lathe spans agree with even-odd membership in the meridian half-plane", "[lathe]", double, float) {
    std::mt19937_64 rng(15);
    for (double scale : {1.0, 1e-6, 1e6, 3.7e2}) {
        for (int kind = 0; kind < 6; ++kind) {
            INFO("scale " << scale << " kind " << kind);
            check_rays<TestType>(make_profile(rng, kind, scale), scale, rng, 120);
        }
    }
}

TEST_CASE("lathe rays from far away keep their crossings", "[lathe]") {
    std::mt19937_64 rng(5);
    for (int kind = 0; kind < 6; ++kind) {
        INFO("kind " << kind);
        check_rays<double>(make_profile(rng, kind, 1), 1, rng, 100, 1e5);
    }
}

TEST_CASE("a revolved rectangle is the tube, a revolved triangle the cone: closed forms", "[lathe]") {
    std::mt19937_64 rng(1);
    Section tube;
    add_path(tube, {{2, 0}, {3, 0}, {3, 1}, {2, 1}});
    finish(tube);
    // A ray through the axis at mid height: the tube's walls at |x| in [2, 3].
    std::vector<csg::PrismSpan<double>> out;
    REQUIRE(spans_of<double>(tube, {-5, 0, 0.5}, {1, 0, 0}, out) == 2);
    CHECK(out[0].s.t0 == Approx(2));
    CHECK(out[0].s.t1 == Approx(3));
    CHECK(out[1].s.t0 == Approx(7));
    CHECK(out[1].s.t1 == Approx(8));
    // Straight down through the wall: the caps z = 1 and z = 0.
    REQUIRE(spans_of<double>(tube, {0, 2.5, 4}, {0, 0, -1}, out) == 1);
    CHECK(out[0].s.t0 == 3);
    CHECK(out[0].s.t1 == 4);
    // Volumes: tube π(3² − 2²)·1, cone π·1²·2/3.
    CHECK(grid_volume(tube, 3, 300) == Approx(5 * M_PI).epsilon(2e-3));
    Section cone;
    add_path(cone, {{0, 0}, {1, 0}, {0, 2}});
    finish(cone);
    CHECK(grid_volume(cone, 1, 300) == Approx(2 * M_PI / 3).epsilon(2e-3));
    // A ray along the cone's slant line (leading coefficient zero: the linear case).
    // In the plane x = 0 the far side is |y| = 1 − z/2: met at t = 1, then the base at t = 2.
    const int n = spans_of<double>(cone, {0, -1, 2}, {0, 0.5, -1}, out);
    REQUIRE(n == 1);
    CHECK(out[0].s.t0 == Approx(1));
    CHECK(out[0].s.t1 == Approx(2));
}

TEST_CASE("lathe normals face out of the filled side", "[lathe]") {
    std::mt19937_64 rng(3);
    int checked = 0;
    for (int kind : {0, 2, 5}) {
        const Section s = make_profile(rng, kind, 1);
        std::vector<csg::PrismSpan<double>> out;
        std::uniform_real_distribution<double> u(-1, 1);
        for (int r = 0; r < 300; ++r) {
            const dvec3 o(4 * u(rng), 4 * u(rng), 2 * u(rng)), d = dvec3(u(rng), u(rng), 0.5 * u(rng)) - o;
            const int n = spans_of<double>(s, o, d, out);
            for (int i = 0; i < n; ++i) {
                const dvec3 n0 = csg::normal_lathe(s.poly, out[i].s.part0, out[i].edge0, o + double(out[i].s.t0) * d);
                const dvec3 n1 = csg::normal_lathe(s.poly, out[i].s.part1, out[i].edge1, o + double(out[i].s.t1) * d);
                // Stepping outward from an entry goes back along the ray, from an exit forward.
                CHECK(glm::dot(n0, d) < 0);
                CHECK(glm::dot(n1, d) > 0);
                ++checked;
            }
        }
    }
    CHECK(checked > 300);
}
