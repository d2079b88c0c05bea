// The swept prism (a top scale 0, a scale differing in x and y, a twist)
// against the even-odd oracle of the section map undone
// (csg::contains_prism: the point scaled and turned back into the shape's
// plane, a textbook point-in-polygon; no code shared with the ray test).
// Random sections (concave stars with holes, self-intersecting scribbles),
// random scales (0 included) and twists, random rays (general, through a
// vertex, parallel to the caps, parallel to the axis), at scales 1e-3 … 1e3:
// membership must be constant between reported crossings and equal
// "inside a reported span" (samples within a small band of a reported end
// skipped), and it must flip across every reported end.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "csg/membership.hpp"
#include "render/primitives/prism.hpp"
#include "tests/render/primitives/polygon_sections.hpp"

using namespace kerf;
using glm::dvec2;
using glm::dvec3;

namespace {

test::Section random_section(std::mt19937_64& rng, int kind, double scale) {
    std::uniform_real_distribution<double> u(-1, 1);
    test::Section s;
    if (kind == 0) {  // a concave star with two holes, off the axis
        test::add_path(s, test::star(rng, {0.3, -0.2}, 1, 11));
        test::add_path(s, test::star(rng, {0.4, -0.1}, 0.2, 5));
        test::add_path(s, test::star(rng, {0.1, -0.4}, 0.15, 4));
    } else if (kind == 1) {  // a self-intersecting scribble
        std::vector<dvec2> p;
        for (int i = 0; i < 8; ++i) p.push_back({u(rng), u(rng)});
        test::add_path(s, p);
    } else {  // a square away from the axis (a twisted bar)
        test::add_path(s, {{0.5, -0.25}, {1.5, -0.25}, {1.5, 0.25}, {0.5, 0.25}});
    }
    for (glm::dvec4& e : s.poly.edges) e *= scale;
    for (dvec2& v : s.vertices) v *= scale;
    test::finish(s);
    return s;
}

struct Params {
    double sx, sy, twist_deg;
};

template <typename T>
int check_rays(const test::Section& s, const Params& q, double scale, std::mt19937_64& rng, int rays) {
    const double c[6] = {-0.3 * scale, 0.9 * scale, q.sx - 1, q.sy - q.sx, q.twist_deg * M_PI / 180, 0};
    REQUIRE(csg::is_swept(c));
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<csg::PrismSpan<T>> out(csg::prism_span_room(s.poly.edges.size(), c));
    std::vector<csg::PrismCrossing<T>> scratch(s.poly.edges.size());
    const double rel = std::is_same_v<T, float> ? 3e-4 : 1e-8;  // band around an end, relative to the ray's reach
    int flips = 0;
    for (int r = 0; r < rays; ++r) {
        dvec3 o(u(rng), u(rng), u(rng));
        o = 4.0 * scale * o / glm::length(o);
        dvec3 target(u(rng) * 1.5 * scale, u(rng) * 1.5 * scale, (0.3 + 0.6 * u(rng)) * scale);
        const int mode = r % 4;
        if (mode == 1) {  // through a vertex of the bottom cap
            target = dvec3(s.vertices[std::size_t(rng() % s.vertices.size())], c[0]);
        } else if (mode == 2) {  // parallel to the caps
            o.z = target.z;
        } else if (mode == 3) {  // parallel to the axis
            o = dvec3(target.x, target.y, 3 * scale);
        }
        const dvec3 d = (target - o) * (0.5 + std::abs(u(rng)));
        const int n =
            csg::intersect_prism<T>(s.poly, c, glm::vec<3, T>(o), glm::vec<3, T>(d), out.data(), scratch.data());
        REQUIRE(n <= int(out.size()));
        const double reach = 8 * scale / glm::length(d);  // the t range of a few object sizes
        const double band = rel * reach;
        auto in_spans = [&](double t) {
            for (int i = 0; i < n; ++i)
                if (out[i].s.t0 < t && t < out[i].s.t1) return true;
            return false;
        };
        auto inside = [&](double t) { return csg::contains_prism(s.poly, c, o + t * d); };
        std::vector<double> ends;
        for (int i = 0; i < n; ++i) {
            INFO("ray " << r << " mode " << mode << " span " << i << " of " << n);
            REQUIRE(out[i].s.t0 < out[i].s.t1);
            if (i > 0) REQUIRE(out[i - 1].s.t1 < out[i].s.t0);
            ends.push_back(out[i].s.t0), ends.push_back(out[i].s.t1);
        }
        // Membership flips across every end that has room on both sides.
        for (std::size_t k = 0; k < ends.size(); ++k) {
            const double t = ends[k];
            const double before = k > 0 ? ends[k - 1] : -1e300, after = k + 1 < ends.size() ? ends[k + 1] : 1e300;
            if (t - before < 4 * band || after - t < 4 * band) continue;
            INFO("ray " << r << " mode " << mode << " end " << k << " t " << t);
            const bool entering = k % 2 == 0;
            CHECK(inside(t - band) == !entering);
            CHECK(inside(t + band) == entering);
            ++flips;
        }
        // And it equals "inside a span" everywhere else along the ray.
        for (int k = 0; k <= 600; ++k) {
            const double t = 3.0 * k / 600.0;
            bool near_end = false;
            for (double e : ends) near_end = near_end || std::abs(e - t) <= band;
            if (near_end) continue;
            INFO("ray " << r << " mode " << mode << " t " << t << " spans " << n);
            REQUIRE(in_spans(t) == inside(t));
        }
    }
    return flips;
}

}  // namespace

TEMPLATE_TEST_CASE("swept prism spans agree with membership of the section map undone", "[prism][swept]", double,
                   float) {
    std::mt19937_64 rng(2015);
    std::uniform_real_distribution<double> u(0, 1);
    const Params fixed[] = {{0, 0, 0}, {2, 0.5, 0}, {0, 1.5, 0}, {1, 1, 90}, {1, 1, -360}, {0, 0, 200},
                            {2.5, 0.3, 720}, {0.5, 0.5, 45}, {1, 3, -30}};
    int flips = 0;
    for (double scale : {1.0, 1e-3, 1e3}) {
        for (const Params& q : fixed) {
            for (int kind = 0; kind < 3; ++kind) {
                INFO("scale " << scale << " sx " << q.sx << " sy " << q.sy << " twist " << q.twist_deg << " kind "
                              << kind);
                flips += check_rays<TestType>(random_section(rng, kind, scale), q, scale, rng, 60);
            }
        }
        for (int k = 0; k < 6; ++k) {  // random parameters
            const Params q{3 * u(rng), 3 * u(rng), 720 * (u(rng) - 0.5)};
            INFO("scale " << scale << " sx " << q.sx << " sy " << q.sy << " twist " << q.twist_deg);
            flips += check_rays<TestType>(random_section(rng, int(rng() % 3), scale), q, scale, rng, 60);
        }
    }
    CHECK(flips > 2000);
}

TEST_CASE("swept prism normals face out of the filled side", "[prism][swept]") {
    std::mt19937_64 rng(4);
    const test::Section s = random_section(rng, 0, 1);
    std::uniform_real_distribution<double> u(-1, 1);
    int checked = 0;
    for (const Params& q : {Params{0, 0, 0}, Params{2, 0.5, 0}, Params{1, 1, 120}, Params{0.3, 1.7, -250}}) {
        const double c[6] = {-0.3, 0.9, q.sx - 1, q.sy - q.sx, q.twist_deg * M_PI / 180, 0};
        std::vector<csg::PrismSpan<double>> out(csg::prism_span_room(s.poly.edges.size(), c));
        std::vector<csg::PrismCrossing<double>> scratch(s.poly.edges.size());
        for (int r = 0; r < 300; ++r) {
            const dvec3 o(3 * u(rng), 3 * u(rng), u(rng)), d = dvec3(0.5 * u(rng), 0.5 * u(rng), 0.3 * u(rng)) - o;
            const int n = csg::intersect_prism<double>(s.poly, c, o, d, out.data(), scratch.data());
            for (int i = 0; i < n; ++i) {
                for (int end = 0; end < 2; ++end) {
                    const double t = end ? out[i].s.t1 : out[i].s.t0;
                    const dvec3 nn = csg::normal_prism(s.poly, c, end ? out[i].s.part1 : out[i].s.part0,
                                                       end ? out[i].edge1 : out[i].edge0, o + t * d);
                    // A step along the normal leaves the solid (unless the point is a rim).
                    const dvec3 p = o + t * d, step = 1e-6 * glm::normalize(nn);
                    if (csg::contains_prism(s.poly, c, p - step) == csg::contains_prism(s.poly, c, p + step)) continue;
                    CHECK(csg::contains_prism(s.poly, c, p - step));
                    CHECK_FALSE(csg::contains_prism(s.poly, c, p + step));
                    ++checked;
                }
            }
        }
    }
    CHECK(checked > 300);
}
