// Rays exactly through vertices and along shared edges of closed meshes: each
// crossing must count once, so a mesh's spans match the chord the convex
// solid's face planes say along the ray (an independent oracle: point
// membership by every face plane, in double). Embree's inclusive float test
// counted such a crossing twice or not at all, breaking the parity.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using glm::dvec3;

namespace {

// Triangles of a convex point set's faces, wound counter-clockwise seen from
// outside (the centroid is inside).
void add_outward(csg::Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, const dvec3& centre) {
    const dvec3 n = glm::cross(m.points[b] - m.points[a], m.points[c] - m.points[a]);
    if (glm::dot(n, m.points[a] - centre) < 0) std::swap(b, c);
    m.triangles.insert(m.triangles.end(), {a, b, c});
}

csg::Mesh cube_mesh() {
    csg::Mesh m;
    for (int c = 0; c < 8; ++c) m.points.push_back({(c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
        for (int t : {0, 1}) add_outward(m, std::uint32_t(q[0]), std::uint32_t(q[t + 1]), std::uint32_t(q[t + 2]), dvec3(0));
    return m;
}

csg::Mesh octahedron_mesh() {
    csg::Mesh m;
    m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) add_outward(m, x, y, z, dvec3(0));
    return m;
}

// OpenSCAD's sphere(r, $fn = n): (n + 1) / 2 rings at polar angles
// 180° (i + 0.5) / rings, each a regular n-gon, closed by two flat caps.
csg::Mesh faceted_sphere(double r, int n) {
    csg::Mesh m;
    const int rings = (n + 1) / 2;
    const double pi = std::acos(-1.0);
    for (int i = 0; i < rings; ++i) {
        const double phi = pi * (i + 0.5) / rings;
        for (int j = 0; j < n; ++j) {
            const double th = 2 * pi * j / n;
            m.points.push_back({r * std::sin(phi) * std::cos(th), r * std::sin(phi) * std::sin(th), r * std::cos(phi)});
        }
    }
    auto at = [n](int i, int j) { return std::uint32_t(i * n + (j % n)); };
    for (int j = 1; j + 1 < n; ++j) {  // caps as fans
        add_outward(m, at(0, 0), at(0, j), at(0, j + 1), dvec3(0));
        add_outward(m, at(rings - 1, 0), at(rings - 1, j), at(rings - 1, j + 1), dvec3(0));
    }
    for (int i = 0; i + 1 < rings; ++i)
        for (int j = 0; j < n; ++j) {
            add_outward(m, at(i, j), at(i + 1, j), at(i + 1, j + 1), dvec3(0));
            add_outward(m, at(i, j), at(i + 1, j + 1), at(i, j + 1), dvec3(0));
        }
    return m;
}

// Each triangle its own three points: no vertex is shared by index.
csg::Mesh soup(const csg::Mesh& m) {
    csg::Mesh s;
    for (std::uint32_t i : m.triangles) {
        s.triangles.push_back(std::uint32_t(s.points.size()));
        s.points.push_back(m.points[i]);
    }
    return s;
}

csg::Leaf mesh_leaf(std::uint32_t mesh, const csg::Mesh& m, const glm::dmat4& world = glm::dmat4(1.0)) {
    csg::Leaf l = make_leaf(csg::PrimKind::Mesh, {}, world);
    l.mesh = mesh;
    l.bounds = csg::Aabb{};
    for (const dvec3& p : m.points) l.bounds.extend(l.world_from_object.point(p));
    return l;
}

// The oracle: signed distance to the convex solid bounded by the mesh's
// face planes (negative inside), from the planes alone.
double convex_distance(const csg::Mesh& m, const dvec3& p) {
    double sd = -1e300;
    for (std::size_t f = 0; f < m.triangles.size(); f += 3) {
        const dvec3 a = m.points[m.triangles[f]];
        const dvec3 n = glm::normalize(glm::cross(m.points[m.triangles[f + 1]] - a, m.points[m.triangles[f + 2]] - a));
        sd = std::max(sd, glm::dot(n, p - a));
    }
    return sd;
}

// The line's chord through the convex solid, by clipping with every plane
// (Cyrus–Beck): where to sample. Empty: t0 >= t1.
void convex_chord(const csg::Mesh& m, const dvec3& o, const dvec3& d, double& t0, double& t1) {
    t0 = -1e300, t1 = 1e300;
    for (std::size_t f = 0; f < m.triangles.size(); f += 3) {
        const dvec3 a = m.points[m.triangles[f]];
        const dvec3 n = glm::cross(m.points[m.triangles[f + 1]] - a, m.points[m.triangles[f + 2]] - a);
        const double num = glm::dot(n, a - o), den = glm::dot(n, d);
        if (den < 0) t0 = std::max(t0, num / den);
        else if (den > 0) t1 = std::min(t1, num / den);
        else if (num < 0) t0 = 1e300;
    }
}

// Point membership along the ray against the spans: a sample clearly inside
// (oracle distance below -tol) must lie in a span, one clearly outside in
// none; a span's ends must lie on the surface. Samples: span ends' and gaps'
// midpoints and 64 points over the chord. Points within tol of the surface
// may go either way (a ray grazing a face or a vertex).
bool spans_agree(const std::vector<render::Span>& spans, const dvec3& o, const dvec3& d,
                 double lo, double hi, double (*dist)(const void*, const dvec3&), const void* solid) {
    const double tol = 1e-7;
    auto covered = [&](double t) {
        for (const render::Span& x : spans)
            if (x.t0 < t && t < x.t1) return true;
        return false;
    };
    auto fine = [&](double t) {
        const double sd = dist(solid, o + t * d);
        return sd < -tol ? covered(t) : sd > tol ? !covered(t) : true;
    };
    double prev = 0;
    for (const render::Span& x : spans) {
        if (std::abs(dist(solid, o + x.t0 * d)) > tol && x.t0 > 0) return false;
        if (std::abs(dist(solid, o + x.t1 * d)) > tol) return false;
        if ((x.t0 > prev && !fine(0.5 * (prev + x.t0))) || !fine(0.5 * (x.t0 + x.t1))) return false;
        prev = x.t1;
    }
    if (!fine(prev + 1e-3)) return false;
    for (int k = 0; k <= 64; ++k)
        if (!fine(std::max(1e-9, lo + (hi - lo) * k / 64))) return false;
    return true;
}

double mesh_distance(const void* m, const dvec3& p) { return convex_distance(*static_cast<const csg::Mesh*>(m), p); }

// Rays exactly through every vertex and through points of every edge, from
// seeded directions, plus axis-aligned ones (exact ties on the cube and the
// octahedron). Calls f(o, d).
template <class F> void vertex_and_edge_rays(const csg::Mesh& m, F f) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    const dvec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 1, 1}, {0.6, -0.8, 0}};
    std::vector<dvec3> targets(m.points.begin(), m.points.end());
    for (std::size_t i = 0; i < m.triangles.size(); i += 3)
        for (int e = 0; e < 3; ++e) {
            const dvec3 a = m.points[m.triangles[i + e]], b = m.points[m.triangles[i + (e + 1) % 3]];
            targets.push_back(0.5 * (a + b));
            targets.push_back(0.25 * a + 0.75 * b);
        }
    for (const dvec3& p : targets) {
        for (const dvec3& axis : axes) f(p - 5.0 * axis, axis);
        for (int k = 0; k < 6; ++k) {
            const dvec3 d = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
            f(p - 4.0 * d, d);
        }
    }
}

// Counts rays whose spans disagree with the oracle.
int disagreements(const csg::Mesh& m, bool use_float) {
    csg::Scene s = make_scene(leaf(mesh_leaf(0, m)));
    s.meshes = {m};
    const render::CsgTracer tracer(s, use_float);
    render::TraceScratch scratch;
    std::vector<render::Span> spans;
    int bad = 0, rays = 0, through = 0;
    vertex_and_edge_rays(m, [&](const dvec3& o, const dvec3& d) {
        double t0, t1;
        convex_chord(m, o, d, t0, t1);
        tracer.inside_spans(render::TraceRay{o, d, 0, 100}, scratch, spans);
        ++rays;
        through += t1 - t0 > 1e-3;
        bad += !spans_agree(spans, o, d, t1 > t0 ? t0 - 1 : 0, t1 > t0 ? t1 + 1 : 10, mesh_distance, &m);
    });
    CHECK(through > 50);
    return bad;
}

}  // namespace

TEST_CASE("rays through mesh vertices and along shared edges count each crossing once", "[render][mesh]") {
    for (bool use_float : {false, true}) {
        INFO("float: " << use_float);
        CHECK(disagreements(cube_mesh(), use_float) == 0);
        CHECK(disagreements(octahedron_mesh(), use_float) == 0);
        CHECK(disagreements(faceted_sphere(2.1, 7), use_float) == 0);
        CHECK(disagreements(faceted_sphere(1.8, 6), use_float) == 0);
        CHECK(disagreements(faceted_sphere(1, 30), use_float) == 0);
        // A triangle soup shares no vertex by index, only by value.
        CHECK(disagreements(soup(faceted_sphere(1.8, 6)), use_float) == 0);
        CHECK(disagreements(soup(octahedron_mesh()), use_float) == 0);
    }
}

TEST_CASE("a faceted sphere minus a smaller one is traced as membership says, at vertices too", "[render][mesh]") {
    // The outer sphere minus the inner one (OpenSCAD's sphere(2.1) and
    // sphere(1.8): the inner's equator vertices poke through the outer's
    // faces, real holes), along rays through every vertex and edge point of
    // both and through a pixel-like grid.
    const csg::Mesh outer = faceted_sphere(2.1, 7), inner = faceted_sphere(1.8, 6);
    csg::Scene s = make_scene(op(Op::Difference, {leaf(mesh_leaf(0, outer)), leaf(mesh_leaf(1, inner))}));
    s.meshes = {outer, inner};
    auto hollow_distance = [&](const dvec3& p) { return std::max(convex_distance(outer, p), -convex_distance(inner, p)); };
    for (bool use_float : {false, true}) {
        INFO("float: " << use_float);
        const render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        int bad = 0, hits = 0;
        // From outside, the first hit must lie on the surface, with no point
        // clearly inside the difference before it, and exist if any is after.
        auto check = [&](const dvec3& o, const dvec3& d) {
            if (hollow_distance(o) < 1e-7) return;  // a camera in the solid sees its next entry
            double t0, t1;
            convex_chord(outer, o, d, t0, t1);
            render::TraceHit hit;
            const bool got = tracer.intersect(render::TraceRay{o, d, 0, 100}, hit, scratch);
            hits += got;
            const double end = got ? hit.t : 100;
            bool ok = !got || std::abs(hollow_distance(o + hit.t * d)) < 1e-7;
            for (int k = 0; k <= 64 && ok && t1 > t0; ++k) {
                const double t = t0 + (t1 - t0) * k / 64;
                ok = !(t < end - 1e-7 && hollow_distance(o + t * d) < -1e-7);
            }
            bad += !ok;
        };
        vertex_and_edge_rays(inner, check);
        vertex_and_edge_rays(outer, check);
        const dvec3 eye(9, -11, 8);
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 100; ++x) {
                const dvec3 aim(-2.2 + 4.4 * x / 99, 0, -2.2 + 4.4 * y / 99);
                check(eye, glm::normalize(aim - eye));
            }
        CHECK(hits > 5000);
        CHECK(bad == 0);
    }
}
