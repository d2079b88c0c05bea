// The extremes (docs/accuracy.md) for every primitive at once: rays starting exactly
// on the surface, rays through poles/edges/corners/rims/apexes, normals
// against the oracle's gradient, identical leaves, and far translations where
// float fails and double holds.
#include <catch2/catch.hpp>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("every primitive: rays starting exactly on the surface", "[prim][extremes]") {
    for (double s : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        for (const auto& [name, leaf] : all_shapes(s)) {
            RayGen gen(42);
            CheckStats st, sf;
            for (int i = 0; i < 3000; ++i) {
                const dvec3 x = surface_point(leaf, gen);
                const dvec3 d = gen.unit() * std::pow(10.0, gen.uniform(-2, 2));
                check_ray<double>(leaf, x, d, 8, s, st);
                check_ray<float>(leaf, x, d, 8, s, sf);
            }
            INFO(name << " scale " << s << ": " << st.first_failure << " / " << sf.first_failure);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
            CHECK(st.hits > 0);
        }
    }
}

TEST_CASE("every primitive: rays through poles, edges, corners, rims and apexes", "[prim][extremes]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        for (const auto& [name, leaf] : all_shapes(s)) {
            RayGen gen(43);
            CheckStats st, sf;
            for (const dvec3& x : special_points(leaf)) {
                for (int i = 0; i < 300; ++i) {
                    const dvec3 u = i < 6 ? dvec3(i % 3 == 0, i % 3 == 1, i % 3 == 2) * (i < 3 ? 1.0 : -1.0)
                                          : gen.unit();  // the axes first, then random
                    const dvec3 o = x - (i % 2 ? 0.0 : 2 * s) * u;
                    check_ray<double>(leaf, o, u, 8, s, st);
                    check_ray<float>(leaf, o, u, 8, s, sf);
                }
            }
            INFO(name << " scale " << s << ": " << st.first_failure << " / " << sf.first_failure);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
        }
    }
}

TEST_CASE("every primitive: outward normals agree with the oracle's gradient", "[prim][extremes]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        for (const auto& [name, leaf] : all_shapes(s)) {
            RayGen gen(44);
            const Ball ball = bounding_ball(leaf, s);
            int checked = 0, wrong = 0;
            std::string first;
            for (int i = 0; i < 2000; ++i) {
                // Through a surface point, so thin shapes are hit as often as fat ones.
                const dvec3 d = gen.unit(), o = surface_point(leaf, gen) - 2 * ball.radius * d;
                kerf::csg::Span<double> sp[2];
                const int n = kerf::csg::intersect_leaf<double>(leaf, o, d, sp);
                for (int k = 0; k < n; ++k)
                    for (int e = 0; e < 2; ++e) {
                        const double t = e ? sp[k].t1 : sp[k].t0;
                        if (!std::isfinite(t)) continue;
                        const dvec3 x = o + t * d;
                        // Central differences of the signed distance; skip edges and
                        // rims, where it is not differentiable (gradient length != 1).
                        const double h = 1e-6 * s;
                        dvec3 g;
                        for (int a = 0; a < 3; ++a) {
                            dvec3 dx(0);
                            dx[a] = h;
                            g[a] = (kerf::csg::surface_distance(leaf, x + dx) - kerf::csg::surface_distance(leaf, x - dx)) /
                                   (2 * h);
                        }
                        if (std::abs(glm::length(g) - 1) > 1e-3) continue;
                        const dvec3 nrm = kerf::csg::object_normal(leaf, x, e ? sp[k].part1 : sp[k].part0);
                        ++checked;
                        if (!(glm::dot(glm::normalize(nrm), glm::normalize(g)) > 1 - 1e-6)) {
                            if (wrong++ == 0) first = describe(leaf, o, d);
                        }
                    }
            }
            INFO(name << " scale " << s << ": " << first);
            CHECK(wrong == 0);
            CHECK(checked > 100);
        }
    }
}

TEMPLATE_TEST_CASE("every primitive: identical leaves give bit-identical spans", "[prim][extremes]", float, double) {
    // The CSG above relies on it: A - A is empty, A ∪ A is A, at every pixel.
    for (const auto& [name, leaf] : all_shapes(1.0)) {
        const Leaf copy = leaf;
        RayGen gen(45);
        const Ball ball = bounding_ball(leaf, 1.0);
        int differ = 0;
        for (int i = 0; i < 5000; ++i) {
            dvec3 o, d;
            gen.ray(ball, 3 * ball.radius, o, d);
            using V = glm::vec<3, TestType>;
            kerf::csg::Span<TestType> a[2], b[2];
            const int na = kerf::csg::intersect_leaf<TestType>(leaf, V(o), V(d), a);
            const int nb = kerf::csg::intersect_leaf<TestType>(copy, V(o), V(d), b);
            bool same = na == nb;
            for (int k = 0; same && k < na; ++k)
                same = a[k].t0 == b[k].t0 && a[k].t1 == b[k].t1 && a[k].part0 == b[k].part0 && a[k].part1 == b[k].part1;
            differ += !same;
        }
        INFO(name);
        CHECK(differ == 0);
    }
}

TEST_CASE("far translations: float loses the solid, double keeps it", "[prim][extremes]") {
    // A solid of size 1 seen from 1e6 away (a translation of 1e6 pushed into
    // the ray origin). Float cannot even represent the origin to better than
    // 0.06; double keeps the crossings within 1e-9 of the size.
    for (const auto& [name, leaf] : all_shapes(1.0)) {
        if (leaf.kind == PrimKind::Plane) continue;  // a plane has no size to lose
        RayGen gen(46);
        CheckStats st, sf;
        for (int i = 0; i < 4000; ++i) {
            const dvec3 d = gen.unit(), o = surface_point(leaf, gen) - 1e6 * d;
            check_ray<double>(leaf, o, d, 8, 1.0, st);
            check_ray<float>(leaf, o, d, 8, 1.0, sf);
        }
        const double max_d = st.rel_err.empty() ? 0 : *std::max_element(st.rel_err.begin(), st.rel_err.end());
        const double max_f = sf.rel_err.empty() ? 0 : *std::max_element(sf.rel_err.begin(), sf.rel_err.end());
        INFO(name << ": double " << max_d << " float " << max_f << " " << st.first_failure << sf.first_failure);
        CHECK(st.failures == 0);  // the documented tolerance (with its |o| term) holds for both
        CHECK(sf.failures == 0);
        CHECK(max_d < 1e-9);   // double: crossings within 1e-9 of the solid's size
        // Float: errors of a visible fraction of the size, or the solid lost.
        CHECK((max_f > 1e-3 || sf.hits < st.hits / 2));
    }
}
