// Test helper: seeded random CSG scenes (every analytic primitive kind, all
// three operations, random affine transforms, depth up to 6) and the
// independent point-membership oracle of a whole csg::Scene.
#pragma once
#include <cmath>
#include <random>

#include "csg/membership.hpp"
#include "tests/render/scene_builder.hpp"

namespace kerf::test {

class RandomCsg {
public:
    explicit RandomCsg(std::uint64_t seed) : rng_(seed) {}

    double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

    glm::dmat4 transform() {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(uni(-1, 1), uni(-1, 1), uni(-1, 1)) + glm::dvec3(1e-3));
        glm::dvec3 s(uni(0.5, 1.2), uni(0.5, 1.2), uni(0.5, 1.2));
        if (pick(6) == 0) s.x = -s.x;  // mirrors too
        return translate(uni(-0.9, 0.9), uni(-0.9, 0.9), uni(-0.9, 0.9)) * rotate_deg(uni(0, 360), axis) *
               scale(s.x, s.y, s.z);
    }

    csg::Leaf primitive(std::uint32_t material, bool allow_plane = true) {
        using K = csg::PrimKind;
        const glm::dmat4 m = transform();
        int kind = pick(7);
        if (!allow_plane && kind == 4) kind = 0;
        switch (kind) {
            case 0: return make_leaf(K::Sphere, {uni(0.3, 1.0)}, m, material);
            case 1: return make_leaf(K::Box, {uni(-1, -0.2), uni(-1, -0.2), uni(-1, -0.2), uni(0.2, 1), uni(0.2, 1), uni(0.2, 1)}, m, material);
            case 2: {
                double r0 = uni(0.2, 0.8), r1 = uni(0.2, 0.8);
                const int cone = pick(4);
                if (cone == 0) r0 = 0;
                if (cone == 1) r1 = 0;
                return make_leaf(K::Cylinder, {uni(-1, -0.2), uni(0.2, 1), r0, r1}, m, material);
            }
            case 3: return make_leaf(K::Torus, {uni(0.5, 1.0), uni(0.1, 0.4)}, m, material);
            case 4: {
                const glm::dvec3 n = glm::normalize(glm::dvec3(uni(-1, 1), uni(-1, 1), uni(-1, 1)) + glm::dvec3(1e-3));
                return make_leaf(K::Plane, {n.x, n.y, n.z, uni(-0.5, 0.5)}, glm::dmat4(1.0), material);
            }
            case 5: return make_leaf(K::Paraboloid, {uni(0.5, 1.5), uni(0.3, 1.0)}, m, material);
            default: {
                const double r = uni(0.4, 1.0);
                return make_leaf(K::Hyperboloid, {uni(0.5, 1.5), r, uni(0.1, 0.9) * r}, m, material);
            }
        }
    }

    Tree tree(int depth, int max_depth) {
        if (depth >= max_depth || (depth > 0 && pick(3) == 0)) return leaf(primitive(std::uint32_t(pick(3))));
        const csg::Op ops[3] = {csg::Op::Union, csg::Op::Intersection, csg::Op::Difference};
        Tree t = op(ops[pick(3)], {});
        const int n = 2 + pick(2);
        for (int k = 0; k < n; ++k) t.kids.push_back(tree(depth + 1, max_depth));
        return t;
    }

    // Wide nodes (more children than the tracer evaluates directly, so they
    // go through per-node BVHs): a union of a few differences, each a random
    // minuend minus many small random solids (some themselves composite).
    Tree wide() {
        Tree u = op(csg::Op::Union, {});
        const int parts = 1 + pick(3);
        for (int p = 0; p < parts; ++p) {
            const csg::Leaf minuend = primitive(0, false);
            Tree d = op(csg::Op::Difference, {leaf(minuend)});
            const int n = 10 + pick(30);
            for (int k = 0; k < n; ++k) {
                Tree small = pick(4) == 0 ? tree(3, 5) : leaf(primitive(1, false));
                const glm::dvec3 at(uni(minuend.bounds.lo.x, minuend.bounds.hi.x), uni(minuend.bounds.lo.y, minuend.bounds.hi.y),
                                    uni(minuend.bounds.lo.z, minuend.bounds.hi.z));
                d.kids.push_back(shrink(std::move(small), uni(0.15, 0.4), at));
            }
            u.kids.push_back(std::move(d));
        }
        for (int k = 0; k < 10; ++k)
            u.kids.push_back(shrink(leaf(primitive(2, false)), 0.3, {uni(-1.2, 1.2), uni(-1.2, 1.2), uni(-1.2, 1.2)}));
        return u;
    }

    // The whole subtree moved by `by`, half-spaces too (far-origin tests).
    static Tree moved(Tree t, const glm::dvec3& by) {
        if (t.op != csg::Op::Leaf) {
            for (Tree& k : t.kids) k = moved(std::move(k), by);
            return t;
        }
        const csg::Leaf& l = t.leaf;
        if (l.kind == csg::PrimKind::Plane) {
            // dot(n, x) < d moved by `by`: dot(n, x) < d + dot(n, by).
            const glm::dvec3 n(l.p[0], l.p[1], l.p[2]);
            t.leaf = make_leaf(l.kind, {n.x, n.y, n.z, l.p[3] + glm::dot(n, by)}, glm::dmat4(1.0), l.material);
            return t;
        }
        glm::dmat4 w(l.world_from_object.linear);
        w[3] = glm::dvec4(l.world_from_object.offset, 1.0);
        t.leaf = make_leaf(l.kind, std::vector<double>(l.p, l.p + 6), translate(by.x, by.y, by.z) * w, l.material);
        return t;
    }

private:
    // Scales a subtree by f and moves its origin to `at`.
    Tree shrink(Tree t, double f, glm::dvec3 at) {
        const glm::dmat4 m = translate(at.x, at.y, at.z) * scale(f, f, f);
        apply(t, m);
        return t;
    }
    static void apply(Tree& t, const glm::dmat4& m) {
        if (t.op != csg::Op::Leaf) {
            for (Tree& k : t.kids) apply(k, m);
            return;
        }
        if (t.leaf.kind == csg::PrimKind::Plane) return;  // half-spaces stay as they are
        const csg::Leaf& l = t.leaf;
        glm::dmat4 w(l.world_from_object.linear);
        w[3] = glm::dvec4(l.world_from_object.offset, 1.0);
        std::vector<double> p(l.p, l.p + 6);
        t.leaf = make_leaf(l.kind, p, m * w, l.material);
    }

    std::mt19937_64 rng_;
};

// Strict point membership of the whole CSG expression (csg/membership.hpp).
inline bool csg_contains(const csg::Scene& s, const glm::dvec3& p) { return csg::contains(s, p); }

// Whether t is the solid's first entry along o + t·d on (0, t_end), by point
// membership alone: outside at every one of 4000 samples before t and just
// before it, inside just after (t infinite: outside at every sample).
inline bool is_first_entry(const csg::Scene& s, const glm::dvec3& o, const glm::dvec3& d, double t, double t_end,
                           double h) {
    constexpr int kSamples = 4000;
    const double step = t_end / kSamples;
    for (int i = 1; i <= kSamples && step * i < t - h; ++i)
        if (csg_contains(s, o + step * i * d)) return false;
    if (std::isinf(t)) return true;
    return !csg_contains(s, o + (t - h) * d) && csg_contains(s, o + (t + h) * d);
}

}  // namespace kerf::test
