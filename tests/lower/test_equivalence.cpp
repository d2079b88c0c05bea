// Lowering must not change the solid. Random scene graphs (all operations,
// empty operations, transforms incl. mirrors and shears, half-spaces) are
// classified point by point twice: on the original graph, with this test's
// own transform composition and inside tests, and on the lowered tree. The
// answers must agree, and every point inside a lowered node must lie in that
// node's (clipped) box.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "tests/lower/graph_builder.hpp"
#include "lower/lower.hpp"
#include "tests/lower/scene_checks.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

bool inside_primitive(csg::PrimKind k, const double* p, const glm::dvec3& u) {
    switch (k) {
        case csg::PrimKind::Sphere: return glm::dot(u, u) <= p[0] * p[0];
        case csg::PrimKind::Box:
            return u.x >= p[0] && u.x <= p[3] && u.y >= p[1] && u.y <= p[4] && u.z >= p[2] && u.z <= p[5];
        case csg::PrimKind::Cylinder: {
            if (u.z < p[0] || u.z > p[1]) return false;
            const double r = p[2] + (p[3] - p[2]) * (u.z - p[0]) / (p[1] - p[0]);
            return std::hypot(u.x, u.y) <= r;
        }
        case csg::PrimKind::Torus: {
            const double d = std::hypot(u.x, u.y) - p[0];
            return d * d + u.z * u.z <= p[1] * p[1];
        }
        case csg::PrimKind::Plane: return p[0] * u.x + p[1] * u.y + p[2] * u.z <= p[3];
        case csg::PrimKind::Paraboloid: return u.z <= p[0] && u.z >= p[0] * (u.x * u.x + u.y * u.y) / (p[1] * p[1]);
        case csg::PrimKind::Hyperboloid: {
            if (std::abs(u.z) > p[0] / 2) return false;
            const double t = 2 * u.z / p[0];
            return u.x * u.x + u.y * u.y <= p[2] * p[2] + (p[1] * p[1] - p[2] * p[2]) * t * t;
        }
        default: return false;
    }
}

bool graph_inside(const graph::SceneGraph& g, std::uint32_t n, const glm::dmat4& world_from_node, const glm::dvec3& x) {
    const graph::Node& node = g.nodes[n];
    auto kid = [&](std::uint32_t i) { return g.child_refs[node.first_child + i]; };
    switch (node.kind) {
        case graph::NodeKind::Primitive:
            return inside_primitive(node.prim, node.p, glm::dvec3(glm::inverse(world_from_node) * glm::dvec4(x, 1)));
        case graph::NodeKind::Intersection: {
            if (node.child_count == 0) return false;
            for (std::uint32_t i = 0; i < node.child_count; ++i)
                if (!graph_inside(g, kid(i), world_from_node, x)) return false;
            return true;
        }
        case graph::NodeKind::Difference: {
            if (node.child_count == 0 || !graph_inside(g, kid(0), world_from_node, x)) return false;
            for (std::uint32_t i = 1; i < node.child_count; ++i)
                if (graph_inside(g, kid(i), world_from_node, x)) return false;
            return true;
        }
        default: {
            const glm::dmat4 m = node.kind == graph::NodeKind::Transform ? world_from_node * g.matrices[node.index] : world_from_node;
            for (std::uint32_t i = 0; i < node.child_count; ++i)
                if (graph_inside(g, kid(i), m, x)) return true;
            return false;
        }
    }
}

// Classifies x on the lowered tree; records box violations.
bool csg_inside(const csg::Scene& s, std::uint32_t n, const glm::dvec3& x, int& outside_box) {
    const csg::Node& node = s.nodes[n];
    bool in = false;
    if (node.op == csg::Op::Leaf) {
        const csg::Leaf& l = s.leaves[node.first];
        in = inside_primitive(static_cast<csg::PrimKind>(l.kind), l.p, l.object_from_world.point(x));
    } else {
        auto kid = [&](std::uint32_t i) { return csg_inside(s, s.children[node.first + i], x, outside_box); };
        if (node.op == csg::Op::Union) {
            for (std::uint32_t i = 0; i < node.count; ++i) in = kid(i) || in;
        } else if (node.op == csg::Op::Intersection) {
            in = true;
            for (std::uint32_t i = 0; i < node.count; ++i) in = kid(i) && in;
        } else {
            in = kid(0);
            for (std::uint32_t i = 1; i < node.count; ++i) in = !kid(i) && in;
        }
    }
    if (in) {
        const double eps = 1e-9;
        for (int a = 0; a < 3; ++a)
            if (x[a] < node.bounds.lo[a] - eps || x[a] > node.bounds.hi[a] + eps) ++outside_box;
    }
    return in;
}

struct RandomScene {
    explicit RandomScene(unsigned seed) : rng(seed) {}
    std::mt19937 rng;
    GraphBuilder b;
    double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

    std::uint32_t primitive() {
        switch (pick(7)) {
            case 0: return b.sphere(u(0.3, 1.5));
            case 1: { const glm::dvec3 lo(u(-1.5, 0), u(-1.5, 0), u(-1.5, 0)); return b.box(lo, lo + glm::dvec3(u(0.3, 2), u(0.3, 2), u(0.3, 2))); }
            case 2: { const double z = u(-1.5, 0); return b.cylinder(z, z + u(0.5, 2.5), pick(3) == 0 ? 0 : u(0.2, 1.2), u(0.2, 1.2)); }
            case 3: { const double R = u(0.5, 1.5); return b.torus(R, R * u(0.1, 0.6)); }
            case 4: return b.plane(glm::normalize(glm::dvec3(u(-1, 1), u(-1, 1), u(-1, 1)) + glm::dvec3(0, 0, 1e-3)), u(-0.5, 1));
            case 5: return b.paraboloid(u(0.5, 2), u(0.3, 1.5));
            default: { const double r = u(0.4, 1.5); return b.hyperboloid(u(0.5, 2.5), r, r * u(0.2, 0.9)); }
        }
    }

    glm::dmat4 transform() {
        glm::dmat4 m(1);
        switch (pick(4)) {
            case 0: m = glm::rotate(glm::dmat4(1), u(-3.2, 3.2), glm::normalize(glm::dvec3(u(-1, 1), u(-1, 1), u(-1, 1)) + glm::dvec3(1e-3))); break;
            case 1: m = glm::scale(glm::dmat4(1), glm::dvec3(u(0.5, 1.5) * (pick(3) ? 1 : -1), u(0.5, 1.5), u(0.5, 1.5) * (pick(3) ? 1 : -1))); break;
            case 2: m[1][0] = u(-0.7, 0.7); m[2][1] = u(-0.7, 0.7); break;
            default: break;
        }
        return glm::translate(glm::dmat4(1), glm::dvec3(u(-1.2, 1.2), u(-1.2, 1.2), u(-1.2, 1.2))) * m;
    }

    std::uint32_t tree(int depth) {
        if (depth == 0 || pick(4) == 0) return primitive();
        const int kind = pick(6);
        if (kind == 4) return b.xform(transform(), tree(depth - 1));
        if (kind == 5) return b.color({u(0, 1), u(0, 1), u(0, 1)}, tree(depth - 1));
        const int n = pick(8) == 0 ? 0 : 1 + pick(4);
        std::vector<std::uint32_t> kids;
        for (int i = 0; i < n; ++i) kids.push_back(tree(depth - 1));
        if (kind == 0 || kind == 3) return b.uni(kids);
        if (kind == 1) return b.inter(kids);
        return b.diff(kids);
    }
};

}  // namespace

TEST_CASE("lowering preserves the solid point by point, and nodes' boxes contain their solids") {
    int non_empty = 0, pruned_something = 0;
    for (int trial = 0; trial < 300; ++trial) {
        RandomScene r(7000 + trial);
        std::vector<std::uint32_t> top;
        for (int i = 0, n = 1 + r.pick(3); i < n; ++i) top.push_back(r.tree(4));
        const graph::SceneGraph& g = r.b.finish(top);
        std::size_t prims = 0;
        for (const auto& n : g.nodes) prims += n.kind == graph::NodeKind::Primitive;
        const csg::Scene s = lower_to_csg(g);
        test::check_structure(s);
        pruned_something += s.leaves.size() < prims;
        std::mt19937 pts(trial);
        std::uniform_real_distribution<double> coord(-4, 4);
        int outside_box = 0, mismatches = 0, inside = 0;
        for (int k = 0; k < 1500; ++k) {
            const glm::dvec3 x(coord(pts), coord(pts), coord(pts));
            const bool want = graph_inside(g, g.root, glm::dmat4(1), x);
            const bool got = s.root != csg::kNone && csg_inside(s, s.root, x, outside_box);
            mismatches += want != got;
            inside += want;
        }
        non_empty += inside > 0;
        INFO("trial " << trial);
        CHECK(mismatches == 0);
        CHECK(outside_box == 0);
    }
    // the generator exercises both sides
    CHECK(non_empty > 100);
    CHECK(pruned_something > 30);
}
