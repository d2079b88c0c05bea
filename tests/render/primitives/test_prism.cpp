// The prism leaf against the even-odd oracle (csg::contains_prism, a
// textbook point-in-polygon that shares no code with the ray test): random
// sections — concave stars with holes, self-intersecting scribbles,
// collinear edges, zero-area sections — random rays, many of them through
// vertices, along edges, parallel to the caps or to the sides, at scales
// 1e-6 … 1e6. At every sample along the ray farther than the tolerance band
// from the surface, membership must equal "inside a reported span"; every
// reported end must lie on the surface (an edge or a cap), so membership
// flips exactly at the reported crossings.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "csg/membership.hpp"
#include "tests/render/primitives/polygon_sections.hpp"
#include "render/primitives/prism.hpp"
#include "render/primitives/prism_grid.hpp"

using namespace kerf;
using test::add_path;
using test::finish;
using test::Section;
using test::seg_distance;
using test::star;
using glm::dvec2;
using glm::dvec3;

namespace {

// Kinds of section, scaled by `scale`.
Section make_section(std::mt19937_64& rng, int kind, double scale) {
    std::uniform_real_distribution<double> u(-1, 1);
    Section s;
    if (kind == 0) {  // concave star with two holes
        add_path(s, star(rng, {0, 0}, 1, 12));
        add_path(s, star(rng, {0.15, 0.1}, 0.2, 5));
        add_path(s, star(rng, {-0.15, -0.1}, 0.15, 4));
    } else if (kind == 1) {  // self-intersecting scribble
        std::vector<dvec2> p;
        for (int i = 0; i < 9; ++i) p.push_back({u(rng), u(rng)});
        add_path(s, p);
    } else if (kind == 2) {  // grid points: collinear edges and a square hole, shared vertices
        add_path(s, {{-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}});
        add_path(s, {{-0.5, -0.5}, {0, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    } else if (kind == 3) {  // zero area: all on one line, and a back-and-forth path
        add_path(s, {{-1, -0.5}, {0, 0}, {1, 0.5}});
        add_path(s, {{-1, 1}, {1, 1}});
    } else {  // overlapping copies: even-odd makes the overlap a hole
        add_path(s, {{-1, -1}, {0.5, -1}, {0.5, 0.5}, {-1, 0.5}});
        add_path(s, {{-0.5, -0.5}, {1, -0.5}, {1, 1}, {-0.5, 1}});
    }
    for (glm::dvec4& e : s.poly.edges) e *= scale;
    for (dvec2& v : s.vertices) v *= scale;
    finish(s);
    return s;
}

// Distance from p to the prism's surface, by brute force (no ray code):
// the sides are the edges times [z0, z1], the caps the section at z0, z1.
// A tapered prism (c[2] ≠ 0) is measured in the section through p (its
// edges scaled by k(z)): an upper bound of the distance to a slanted side,
// within 1/cos(slope) of it, which the bands below allow for.
double surface_gap(const Section& s, const double* c, const dvec3& p) {
    const double zc = std::clamp(p.z, c[0], c[1]);
    const double k = 1 + c[2] * (zc - c[0]) / (c[1] - c[0]);
    double edge = 1e300;
    for (const glm::dvec4& e : s.poly.edges) edge = std::min(edge, seg_distance(k * e, {p.x, p.y}));
    const double dz = std::max({0.0, c[0] - p.z, p.z - c[1]});
    // Is (x, y) in the section at zc? Asked of the section at mid height, rescaled.
    const double zm = 0.5 * (c[0] + c[1]), km = 1 + c[2] * (zm - c[0]) / (c[1] - c[0]);
    const bool in_xy = csg::contains_prism(s.poly, c, {p.x * km / k, p.y * km / k, zm});
    const double cap = in_xy ? std::min(std::abs(p.z - c[0]), std::abs(p.z - c[1])) : 1e300;
    return std::min(std::hypot(edge, dz), cap);
}

// Random rays against the section: the oracle at `samples` points along
// each, and the same spans bit for bit through grids of the section
// (coarse, default, fine) as from testing every edge.
template <typename T>
void check_rays(const Section& s, double scale, std::mt19937_64& rng, int rays, double taper = 0,
                int samples = 400) {
    const double c[6] = {-0.3 * scale, 0.4 * scale, taper, 0, 0, 0};
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<csg::PrismSpan<T>> out(csg::prism_span_room(s.poly.edges.size())), via_grid(out.size());
    std::vector<csg::PrismCrossing<T>> scratch(s.poly.edges.size());
    std::vector<csg::PrismGrid> grids;
    for (double cells_per_edge : {0.05, 2.0, 40.0}) grids.push_back(csg::build_prism_grid(s.poly, 0, cells_per_edge));
    const double tol_k = std::is_same_v<T, float> ? 2e-5 : 1e-11;
    for (int r = 0; r < rays; ++r) {
        dvec3 o(u(rng), u(rng), u(rng));
        o = 3.0 * scale * o / glm::length(o);
        dvec3 target(u(rng) * scale, u(rng) * scale, u(rng) * 0.5 * scale);
        const int mode = r % 5;
        if (mode == 1) {  // through a vertex
            const dvec2 v = s.vertices[std::size_t(rng() % s.vertices.size())];
            target = dvec3(v, target.z);
        } else if (mode == 2) {  // along an edge's line
            const glm::dvec4 e = s.poly.edges[std::size_t(rng() % s.poly.edges.size())];
            o = dvec3(e.x, e.y, 0.1 * scale) - 2.0 * dvec3(e.z - e.x, e.w - e.y, 0);
            target = dvec3(e.z, e.w, 0.1 * scale);
        } else if (mode == 3) {  // parallel to the caps
            target.z = o.z = u(rng) * 0.5 * scale;
        } else if (mode == 4) {  // parallel to the sides
            o = dvec3(target.x, target.y, 3 * scale);
        }
        const dvec3 d = (target - o) * (0.5 + std::abs(u(rng)));
        const int n = csg::intersect_prism<T>(s.poly, c, glm::vec<3, T>(o), glm::vec<3, T>(d), out.data(),
                                              scratch.data());
        REQUIRE(n <= int(out.size()));
        for (const csg::PrismGrid& g : grids) {
            const int ng = csg::intersect_prism<T>(s.poly, c, glm::vec<3, T>(o), glm::vec<3, T>(d), via_grid.data(),
                                                   scratch.data(), -std::numeric_limits<T>::infinity(),
                                                   std::numeric_limits<T>::infinity(), &g);
            INFO("ray " << r << " mode " << mode << " grid " << g.nx << " x " << g.ny);
            REQUIRE(ng == n);
            for (int i = 0; i < n; ++i) {
                REQUIRE(via_grid[i].s.t0 == out[i].s.t0);
                REQUIRE(via_grid[i].s.t1 == out[i].s.t1);
                REQUIRE(via_grid[i].s.part0 == out[i].s.part0);
                REQUIRE(via_grid[i].s.part1 == out[i].s.part1);
                REQUIRE(via_grid[i].edge0 == out[i].edge0);
                REQUIRE(via_grid[i].edge1 == out[i].edge1);
            }
        }
        const double tol = tol_k * 8 * scale * (1 + std::abs(taper));  // world length; |o|, |t·d| are a few times scale
        std::vector<double> ends;
        for (int i = 0; i < n; ++i) {
            INFO("span " << i << " of " << n << ": " << out[i].s.t0 << " .. " << out[i].s.t1 << " parts "
                          << int(out[i].s.part0) << " " << int(out[i].s.part1) << " ray " << r << " mode " << mode);
            REQUIRE(out[i].s.t0 < out[i].s.t1);
            if (i > 0) REQUIRE(out[i - 1].s.t1 < out[i].s.t0);
            for (double t : {double(out[i].s.t0), double(out[i].s.t1)}) {
                ends.push_back(t);
                CHECK(surface_gap(s, c, o + t * d) <= tol);
            }
        }
        // Membership at samples away from the surface.
        const double tlen = glm::length(d);
        for (int k = 0; k <= samples; ++k) {
            const double t = -1.0 + 3.0 * k / samples;
            const dvec3 p = o + t * d;
            if (surface_gap(s, c, p) <= 8 * tol) continue;  // 8: the in-section distance of a slanted side
            bool near_end = false;
            for (double e : ends) near_end = near_end || std::abs(e - t) * tlen <= 4 * tol;
            if (near_end) continue;
            bool in_span = false;
            for (int i = 0; i < n; ++i) in_span = in_span || (out[i].s.t0 < t && t < out[i].s.t1);
            INFO("ray " << r << " mode " << mode << " t " << t);
            REQUIRE(in_span == csg::contains_prism(s.poly, c, p));
        }
    }
}

}  // namespace

TEMPLATE_TEST_CASE("prism spans agree with even-odd membership", "[prism]", double, float) {
    std::mt19937_64 rng(15);
    for (double scale : {1.0, 1e-6, 1e6, 3.7e2}) {
        for (int kind = 0; kind < 5; ++kind) {
            INFO("scale " << scale << " kind " << kind);
            const Section s = make_section(rng, kind, scale);
            check_rays<TestType>(s, scale, rng, 300);
        }
    }
}

TEMPLATE_TEST_CASE("tapered prism spans agree with even-odd membership of the scaled section", "[prism]", double,
                   float) {
    std::mt19937_64 rng(16);
    for (double taper : {-0.5, 1.0, -0.9, 3.0}) {
        for (double scale : {1.0, 1e-6, 1e6}) {
            for (int kind = 0; kind < 5; ++kind) {
                INFO("taper " << taper << " scale " << scale << " kind " << kind);
                const Section s = make_section(rng, kind, scale);
                check_rays<TestType>(s, scale, rng, 150, taper);
            }
        }
    }
}

// Sections of thousands of edges (the case the grid is for): a 10,000-point
// star with a 2,000-point star hole and a ring of 1,000 collinear edges
// along one line, and a 4,000-edge zero-area zigzag, at several scales.
// Fewer oracle samples per ray: each costs a pass over every edge.
TEMPLATE_TEST_CASE("prisms of 10,000 edges agree with even-odd membership", "[prism]", double, float) {
    std::mt19937_64 rng(21);
    for (double scale : {1.0, 1e-6, 1e6}) {
        Section s;
        add_path(s, star(rng, {0, 0}, 1, 10000));
        add_path(s, star(rng, {0.1, -0.05}, 0.25, 2000));
        std::vector<dvec2> line;
        for (int i = 0; i <= 500; ++i) line.push_back({-0.9 + 1.8 * i / 500, 0.7});
        for (int i = 499; i > 0; --i) line.push_back({-0.9 + 1.8 * i / 500, 0.75});
        add_path(s, line);
        for (glm::dvec4& e : s.poly.edges) e *= scale;
        for (dvec2& v : s.vertices) v *= scale;
        finish(s);
        INFO("scale " << scale);
        check_rays<TestType>(s, scale, rng, 25, 0, 24);
        check_rays<TestType>(s, scale, rng, 10, 0.5, 24);
    }
    Section zig;
    std::vector<dvec2> z;
    for (int i = 0; i < 4000; ++i) z.push_back({-1 + 2.0 * i / 4000, 0.3 * (i % 2) - 0.15});
    for (int i = 3999; i >= 0; --i) z.push_back({-1 + 2.0 * i / 4000, 0.3 * (i % 2) - 0.15});
    add_path(zig, z);
    finish(zig);
    check_rays<TestType>(zig, 1, rng, 40, 0, 24);
}

// Rays grazing a grid's cells: along its rows and columns, through its
// corners, and along edges lying on cell boundaries.
TEMPLATE_TEST_CASE("grid walks agree with testing every edge on grazing rays", "[prism]", double, float) {
    std::mt19937_64 rng(22);
    Section s;  // an 8 x 8 checkerboard of squares: edges on every grid line
    for (int i = 0; i < 8; ++i)
        for (int j = (i % 2); j < 8; j += 2)
            add_path(s, {{i / 4.0 - 1, j / 4.0 - 1}, {i / 4.0 - 0.75, j / 4.0 - 1}, {i / 4.0 - 0.75, j / 4.0 - 0.75},
                         {i / 4.0 - 1, j / 4.0 - 0.75}});
    finish(s);
    const double c[6] = {-0.3, 0.4, 0, 0, 0, 0};
    std::vector<csg::PrismSpan<TestType>> a(csg::prism_span_room(s.poly.edges.size())), b(a.size());
    std::vector<csg::PrismCrossing<TestType>> scratch(s.poly.edges.size());
    std::uniform_real_distribution<double> u(-1, 1);
    using V = glm::vec<3, TestType>;
    int crossed = 0;
    for (double cells_per_edge : {0.1, 0.5, 1.0, 2.0, 7.0}) {
        const csg::PrismGrid g = csg::build_prism_grid(s.poly, 0, cells_per_edge);
        for (int r = 0; r < 2000; ++r) {
            // Along a grid line (x or y = k/8 or k/4), nearly along it, or through two vertices.
            const double k = std::round(8 * u(rng)) / 8, off = r % 3 == 0 ? 0 : std::ldexp(u(rng), -40 + int(rng() % 30));
            dvec3 o, d;
            if (r % 4 < 2) {
                o = dvec3(-3, k + off, 0.1 * u(rng));
                d = dvec3(6, off * u(rng), 0.05 * u(rng));
            } else {
                o = dvec3(k + off, -3, 0.1 * u(rng));
                d = dvec3(off * u(rng), 6, 0.05 * u(rng));
            }
            if (r % 4 == 1 || r % 4 == 3) std::swap(o.x, o.y), std::swap(d.x, d.y);
            if (r % 7 == 0) {  // through two vertices
                const dvec2 p = s.vertices[rng() % s.vertices.size()], q = s.vertices[rng() % s.vertices.size()];
                if (p == q) continue;
                o = dvec3(p - 2.0 * (q - p), 0.05);
                d = dvec3(q - p, 0.01 * u(rng));
            }
            const int na = csg::intersect_prism<TestType>(s.poly, c, V(o), V(d), a.data(), scratch.data());
            const int nb = csg::intersect_prism<TestType>(s.poly, c, V(o), V(d), b.data(), scratch.data(),
                                                          -std::numeric_limits<TestType>::infinity(),
                                                          std::numeric_limits<TestType>::infinity(), &g);
            INFO("ray " << r << " cells per edge " << cells_per_edge);
            REQUIRE(na == nb);
            crossed += na > 0;
            for (int i = 0; i < na; ++i) {
                REQUIRE(a[i].s.t0 == b[i].s.t0);
                REQUIRE(a[i].s.t1 == b[i].s.t1);
                REQUIRE(a[i].edge0 == b[i].edge0);
                REQUIRE(a[i].edge1 == b[i].edge1);
            }
        }
    }
    CHECK(crossed > 2000);
}

TEST_CASE("a prism's window only drops what lies outside it", "[prism]") {
    std::mt19937_64 rng(7);
    const Section s = make_section(rng, 0, 1);
    const double c[6] = {-0.3, 0.4, 0, 0, 0, 0};
    std::vector<csg::PrismSpan<double>> full(csg::prism_span_room(s.poly.edges.size())), part(full.size());
    std::vector<csg::PrismCrossing<double>> scratch(s.poly.edges.size());
    std::uniform_real_distribution<double> u(-1, 1);
    for (int r = 0; r < 500; ++r) {
        const dvec3 o(3 * u(rng), 3 * u(rng), 0.05 * u(rng)), d = dvec3(u(rng), u(rng), 0.01 * u(rng)) - o / 3.0;
        const int nf = csg::intersect_prism<double>(s.poly, c, o, d, full.data(), scratch.data());
        const double wa = 1 + u(rng), wb = wa + std::abs(u(rng));
        const int np = csg::intersect_prism<double>(s.poly, c, o, d, part.data(), scratch.data(), wa, wb);
        // Every full span overlapping the window appears, with the same ends.
        int j = 0;
        for (int i = 0; i < nf; ++i) {
            if (full[i].s.t1 < wa || full[i].s.t0 > wb) continue;
            REQUIRE(j < np);
            while (j < np && part[j].s.t1 < wa) ++j;
            REQUIRE(j < np);
            CHECK(part[j].s.t0 == full[i].s.t0);
            CHECK(part[j].s.t1 == full[i].s.t1);
            ++j;
        }
    }
}

TEST_CASE("prism normals face out of the filled side", "[prism]") {
    std::mt19937_64 rng(3);
    const Section s = make_section(rng, 0, 1);
    const double c[6] = {-0.3, 0.4, 0, 0, 0, 0};
    std::vector<csg::PrismSpan<double>> out(csg::prism_span_room(s.poly.edges.size()));
    std::vector<csg::PrismCrossing<double>> scratch(s.poly.edges.size());
    std::uniform_real_distribution<double> u(-1, 1);
    int checked = 0;
    for (int r = 0; r < 300; ++r) {
        const dvec3 o(3 * u(rng), 3 * u(rng), u(rng)), d = dvec3(0.5 * u(rng), 0.5 * u(rng), 0.2 * u(rng)) - o;
        const int n = csg::intersect_prism<double>(s.poly, c, o, d, out.data(), scratch.data());
        for (int i = 0; i < n; ++i) {
            const dvec3 n0 = csg::normal_prism(s.poly, c, out[i].s.part0, out[i].edge0);
            const dvec3 n1 = csg::normal_prism(s.poly, c, out[i].s.part1, out[i].edge1);
            // Stepping outward from an entry goes back along the ray, from an exit forward.
            CHECK(glm::dot(n0, d) < 0);
            CHECK(glm::dot(n1, d) > 0);
            ++checked;
        }
    }
    CHECK(checked > 100);
}
