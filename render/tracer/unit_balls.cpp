// The balls of unit_balls.hpp, built once per scene.
#include "render/tracer/unit_balls.hpp"

#include <algorithm>

namespace kerf::render {

namespace {

// Upper bound on the spectral norm of m (the largest stretch of a vector):
// the square root of a Gershgorin bound on mᵀm's largest eigenvalue, which
// is exact for rotations times a uniform scale (the usual case), and never
// below the true norm.
double stretch_bound(const glm::dmat3& m) {
    const glm::dmat3 a = glm::transpose(m) * m;
    double worst = 0;
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(a[0][i]) + std::abs(a[1][i]) + std::abs(a[2][i]));
    return std::sqrt(worst) * (1 + 1e-12);
}

Ball node_ball(const csg::Scene& scene, std::uint32_t id, int depth) {
    const csg::Node& n = scene.nodes[id];
    if (depth > 64) return {};  // deep chains: not worth following
    switch (n.op) {
        case csg::Op::Leaf: {
            const csg::Leaf& leaf = scene.leaves[n.first];
            if (leaf.kind != csg::PrimKind::Sphere) return {};
            return {leaf.world_from_object.offset, leaf.p[0] * stretch_bound(leaf.world_from_object.linear)};
        }
        case csg::Op::Difference: return node_ball(scene, scene.children[n.first], depth + 1);
        case csg::Op::Intersection: {
            Ball best;
            for (std::uint32_t k = 0; k < n.count; ++k) {
                const Ball b = node_ball(scene, scene.children[n.first + k], depth + 1);
                if (b.r >= 0 && (best.r < 0 || b.r < best.r)) best = b;
            }
            return best;
        }
        case csg::Op::Union: return {};
    }
    return {};
}

}  // namespace

std::vector<Ball> unit_balls(const csg::Scene& scene, const std::vector<std::uint32_t>& units,
                             const std::vector<double>& pad) {
    std::vector<Ball> out(units.size());
    bool any = false;
    for (std::size_t i = 0; i < units.size(); ++i) {
        if (scene.nodes[units[i]].op == csg::Op::Leaf) continue;
        out[i] = node_ball(scene, units[i], 0);
        if (out[i].r < 0 || !std::isfinite(out[i].r) || !std::isfinite(glm::dot(out[i].c, out[i].c))) {
            out[i] = {};
            continue;
        }
        // 1e-9 relative: far above the double round-off of the stretch and
        // of the leaf's own sphere test; 4 degenerate rules: beyond every
        // window slack of the unit's evaluation.
        out[i].r = out[i].r * (1 + 1e-9) + 4 * pad[units[i]];
        any = true;
    }
    if (!any) out.clear();
    return out;
}

}  // namespace kerf::render
