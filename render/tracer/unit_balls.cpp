// The balls of unit_balls.hpp, built once per scene.
#include "render/tracer/unit_balls.hpp"

#include <algorithm>

#include "render/tracer/parallel_build.hpp"

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

// The sphere leaf `id`'s radius bounds: the largest and smallest stretch of
// its world_from_object (the smallest as 1 / the largest of the inverse);
// r < 0 when `id` is no sphere leaf.
void sphere_radii(const csg::Scene& scene, std::uint32_t id, double& r_out, double& r_in) {
    r_out = r_in = -1;
    const csg::Node& n = scene.nodes[id];
    if (n.op != csg::Op::Leaf) return;
    const csg::Leaf& leaf = scene.leaves[n.first];
    if (leaf.kind != csg::PrimKind::Sphere) return;
    r_out = leaf.p[0] * stretch_bound(leaf.world_from_object.linear);
    r_in = leaf.p[0] / stretch_bound(leaf.object_from_world.linear);
}

// The ball around the intersection of balls p and q, when smaller than
// both: the plane of their circle of intersection cuts the lens into two
// caps; a cap no more than a hemisphere (its ball's centre on the other
// side of the plane, or on it) lies in the ball on that circle (points of
// the cap at height z above the plane are at most a² − z² from its axis).
// A lens of two spheres (1.2 apart, radii 1) lies in a ball of 0.8, not 1:
// rays between the two miss the unit without evaluating it.
Ball lens_ball(const Ball& p, const Ball& q) {
    const Ball& small = p.r <= q.r ? p : q;
    const glm::dvec3 axis = q.c - p.c;
    const double d = glm::length(axis), big = std::max(p.r, q.r);
    // Nearly concentric: the plane's place would be lost to round-off.
    if (!(d > 1e-3 * big)) return small;
    // From p's centre to the plane (round-off ~1e3 ulps of the radii at most).
    const double x = (d * d + p.r * p.r - q.r * q.r) / (2 * d);
    if (!(x >= 0 && d - x >= 0)) return small;
    // a² grown by 1e-12 of the radius², beyond the round-off of x² (a
    // near-tangent pair's tiny lens keeps a ball of 1e-6 of it at least).
    const double a = std::sqrt(std::max(0.0, p.r * p.r - x * x) + 1e-12 * big * big);
    if (!(a < small.r)) return small;
    return {p.c + (x / d) * axis, a};
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
            // The smallest operand ball, or the lens of two of them.
            std::vector<Ball> balls;
            Ball best;
            for (std::uint32_t k = 0; k < n.count; ++k) {
                const Ball b = node_ball(scene, scene.children[n.first + k], depth + 1);
                if (b.r < 0) continue;
                for (const Ball& other : balls) {
                    const Ball l = lens_ball(b, other);
                    if (best.r < 0 || l.r < best.r) best = l;
                }
                if (best.r < 0 || b.r < best.r) best = b;
                if (balls.size() < 8) balls.push_back(b);
            }
            return best;
        }
        case csg::Op::Union: return {};
    }
    return {};
}

}  // namespace

std::vector<Ball> unit_balls(const csg::Scene& scene, const std::vector<std::uint32_t>& units,
                             const std::vector<double>& pad, bool leaves) {
    std::vector<Ball> out;
    reserve_populated(out, units.size());
    out.resize(units.size());
    parallel_for_build(units.size(), [&](std::size_t i) {
        if (scene.nodes[units[i]].op == csg::Op::Leaf && !leaves) return;
        out[i] = node_ball(scene, units[i], 0);
        if (out[i].r < 0 || !std::isfinite(out[i].r) || !std::isfinite(glm::dot(out[i].c, out[i].c))) {
            out[i] = {};
            return;
        }
        // 1e-9 relative: far above the double round-off of the stretch and
        // of the leaf's own sphere test; 4 degenerate rules: beyond every
        // window slack of the unit's evaluation.
        out[i].r = out[i].r * (1 + 1e-9) + 4 * pad[units[i]];
    });
    // (A kept ball has r >= 0: a dropped one is Ball{}, r < 0.)
    if (std::none_of(out.begin(), out.end(), [](const Ball& b) { return b.r >= 0; })) out.clear();
    return out;
}

std::vector<SphereMinus> sphere_minus_units(const csg::Scene& scene, const std::vector<std::uint32_t>& units,
                                            const std::vector<double>& pad, std::vector<SubBound>& subs) {
    // Most crowds have no difference unit: no per-unit table to fill and drop.
    if (std::none_of(units.begin(), units.end(), [&](std::uint32_t u) { return scene.nodes[u].op == csg::Op::Difference; }))
        return {};
    std::vector<SphereMinus> out(units.size());
    bool any = false;
    for (std::size_t i = 0; i < units.size(); ++i) {
        const csg::Node& n = scene.nodes[units[i]];
        if (n.op != csg::Op::Difference || n.count < 2 || n.count - 1 > SphereMinus::kMaxSubs) continue;
        double r_out, r_in;
        sphere_radii(scene, scene.children[n.first], r_out, r_in);
        const double e = pad[units[i]];
        // The same padding as unit_balls, inwards for what must lie inside.
        r_in = r_in * (1 - 1e-9) - 4 * e;
        if (r_out < 0 || !(r_in > 0)) continue;
        SphereMinus u;
        u.r_in = r_in;
        u.first = std::uint32_t(subs.size());
        bool ok = true;
        for (std::uint32_t k = 1; k < n.count && ok; ++k) {
            const std::uint32_t id = scene.children[n.first + k];
            const csg::Aabb& b = scene.nodes[id].bounds;
            SubBound s;
            s.box = {b.lo - glm::dvec3(4 * e), b.hi + glm::dvec3(4 * e)};
            sphere_radii(scene, id, s.r_out, s.r_in);
            // A box no smaller than the minuend's ball (a cutting half-space
            // made of a big cube) would only ever cover it: the chords could
            // prove nothing, and computing them would be waste.
            if (s.r_out < 0 && !(0.5 * glm::length(b.hi - b.lo) < r_out)) ok = false;
            if (s.r_out >= 0) {
                s.c = scene.leaves[scene.nodes[id].first].world_from_object.offset;
                s.r_out = s.r_out * (1 + 1e-9) + 4 * e;
                s.r_in = s.r_in * (1 - 1e-9) - 4 * e;
                if (!(s.r_in > 0)) s.r_in = -1;
            }
            ok = ok && !b.empty() && std::isfinite(glm::dot(s.box.lo, s.box.lo)) && std::isfinite(glm::dot(s.box.hi, s.box.hi)) &&
                 std::isfinite(s.r_out) && std::isfinite(glm::dot(s.c, s.c));
            subs.push_back(s);
        }
        if (!ok) {
            subs.resize(u.first);
            continue;
        }
        u.count = n.count - 1;
        out[i] = u;
        any = true;
    }
    if (!any) out.clear();
    return out;
}

}  // namespace kerf::render
