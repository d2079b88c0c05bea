// The queries of a bare-sphere crowd's cone rays (bare_spheres.hpp). Each
// answers as CsgTracer::intersect / occluded do for the same ray: the same
// early out where the line misses `reach` (make_state's slab test), the
// same cone (ray_cone), its units in the same order with the same stop,
// and per unit the tests of bare_spheres.hpp; ties go by unit index
// (first_hit.cpp, take_entry). Only the set-up the general query makes
// for Embree (the float ray, the Embree context) is left out.
#include "render/tracer/bare_spheres.hpp"

#include <cmath>

namespace kerf::render {

int bare_first_hit(const CsgTracer::Impl& impl, const TraceRay& ray, TraceHit& hit, TraceScratch& scratch) {
    RayState st;
    if (!make_state(st, &impl, ray, scratch, false)) return 0;
    if (!impl.sphere_grid.empty()) return grid_first_hit(st, ray, hit);
    const RayCone* cone = ray_cone(st, ray, true);
    if (!cone) return -1;
    NearestBare near{ray.tfar};
    const double stop = st.len * (1 + 1e-9);
    // A ray from exactly the camera: each unit's ball test takes the terms
    // of its origin from the apex (Apex::at_p: w = c - p and the grown
    // radius squared, the numbers ball_misses finds for it). Every unit
    // of a cone has its ball (Impl::build_apexes).
    const Apex& ap = impl.apexes[cone->apex];
    const Apex::AtP* at = ap.terms_at(st.o);
    const double inv_len2 = st.inv_len * st.inv_len;
    for (const ConeUnit& u : cone->units) {
        if (u.key > near.best * stop) break;
        if (!at) {
            near.offer(st, u.item, impl.top.items[u.item], ray.tnear);
        } else if (!ball_misses_from(at[u.j].w, at[u.j].rr2, st.d, inv_len2, ray.tnear, near.best)) {
            near.take(st, u.item, impl.top.items[u.item], ray.tnear);
        }
    }
    return near.answer(hit);
}

namespace {

// Whether the ray's line passes every one of the units' balls farther than
// its own ball test grows them (unit_ball_misses: 4·eps_ray, eps_ray at most
// eps_per_distance·|o|₁, and ball_slack·|c - o|₁), with 1e-6 of that
// radius and 1e-12 of |c - o|₁ to spare for the rounding of either test:
// then each rejects the ray by its ball, whatever the window, and none
// blocks it. No ray state needed (a lit point whose listed neighbour
// shadows another part of its sphere).
bool passes_clear(const CsgTracer::Impl& impl, const TraceRay& ray, const std::uint32_t* units, int n) {
    const glm::dvec3& o = ray.o;
    const double inv_dd = 1 / glm::dot(ray.d, ray.d);
    const double slack_abs = 4 * impl.eps_per_distance * (std::abs(o.x) + std::abs(o.y) + std::abs(o.z));
    for (int i = 0; i < n; ++i) {
        const Ball& b = impl.top.balls[units[i]];
        const glm::dvec3 w = b.c - o;
        const glm::dvec3 q = w - glm::dot(w, ray.d) * inv_dd * ray.d;
        const double w1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
        const double r = grown_radius(b.r, slack_abs, impl.ball_slack, w1) * (1 + 1e-6) + 1e-12 * w1;
        if (!(glm::dot(q, q) > r * r)) return false;
    }
    return true;
}

// Whether unit `item` (a moved sphere leaf) provably blocks the ray, as
// bare_sphere_blocks would find: the line passes within 0.9 of the
// sphere's radius of its centre, and the chord's part in the window is
// longer than the degenerate rule (here bounded above, |o|₁ for |o|) by
// 1e-9 of the distances, far beyond the round-off of either computation.
// Then the ball and box tests pass and the sphere's span overlaps the
// window by more than the rule: blocked, without the ray's state or the
// sphere's exact solve (most of a lattice's shadowed points).
bool proves_blocked(const CsgTracer::Impl& impl, const TraceRay& ray, std::uint32_t item) {
    const std::uint32_t node = impl.top.items[item];
    const std::uint32_t leaf = impl.scene.nodes[node].first;
    if (!impl.leaf_shift_only[leaf]) return false;
    const double r = impl.scene.leaves[leaf].p[0];
    const glm::dvec3& o = ray.o;
    const glm::dvec3 w = -impl.scene.leaves[leaf].object_from_world.offset - o;  // centre - o
    const double dd = glm::dot(ray.d, ray.d);
    const double tc = glm::dot(w, ray.d) / dd;
    const glm::dvec3 q = w - tc * ray.d;
    const double q2 = glm::dot(q, q);
    if (!(q2 < 0.81 * r * r)) return false;
    const double len = std::sqrt(dd), h = std::sqrt((r * r - q2) / dd);
    const double o1 = std::abs(o.x) + std::abs(o.y) + std::abs(o.z);
    const double w1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
    const double rule = (impl.node_eps[node] + impl.eps_per_distance * o1) / len;
    const double overlap = std::min(tc + h, ray.tfar) - std::max(tc - h, ray.tnear);
    return overlap > rule + 1e-9 * (w1 + r + o1) / len;
}

}  // namespace

// A shadow ray's answer is whether any unit blocks it, whatever order they
// are asked in, and every path (cone, grid, the general query) answers it
// with bare_sphere_blocks' numbers for each unit it keeps, keeping every
// unit that blocks. So the unit that blocked the thread's last blocked ray
// is asked first: where it blocks this one too (most shadowed points of a
// lattice: their neighbours are shadowed by the same sphere), the answer
// is the same without the cone's lookup or the grid's walk.
namespace {

// bare_occluded past the lists: with the ray's state (out of line, so a ray
// the lists answer pays for no RayState's frame). `listed`: the units a
// list names (nlisted > 0), else -1.
[[gnu::noinline]] int bare_occluded_state(const CsgTracer::Impl& impl, const TraceRay& ray, TraceScratch& scratch,
                                          std::uint32_t skip, const std::uint32_t* listed, int nlisted) {
    RayState st;
    if (!make_state(st, &impl, ray, scratch, false)) return 0;
    if (nlisted > 0) {
        for (int i = 0; i < nlisted; ++i)
            if (bare_sphere_blocks(st, listed[i], impl.top.items[listed[i]], ray.tnear, ray.tfar)) return 1;
        return 0;
    }
    std::uint32_t& last = scratch.blocker;
    if (scratch.blocker_owner == impl.id && last != skip &&
        bare_sphere_blocks(st, last, impl.top.items[last], ray.tnear, ray.tfar))
        return 1;
    const auto blocked = [&](std::uint32_t item) {
        scratch.blocker_owner = impl.id;
        last = item;
        return 1;
    };
    if (!impl.sphere_grid.empty()) {
        std::uint32_t by = csg::kNone;
        const int r = grid_occluded(st, ray, skip, by);
        return r == 1 ? blocked(by) : r;
    }
    const RayCone* cone = ray_cone(st, ray, false);
    if (!cone) return -1;
    // A point of the segment is within (tfar - t)·|d| + rho of the light.
    const double seg = (ray.tfar - ray.tnear) * st.len * (1 + 1e-9);
    for (const ConeUnit& u : cone->units) {
        if (u.key > seg) break;
        if (u.item != skip && bare_sphere_blocks(st, u.item, impl.top.items[u.item], ray.tnear, ray.tfar))
            return blocked(u.item);
    }
    return 0;
}

}  // namespace

int bare_occluded(const CsgTracer::Impl& impl, const TraceRay& ray, TraceScratch& scratch, std::uint32_t skip) {
    // A ray from a sphere to a point light: the few units that may block it
    // (toward_light.hpp), when they are few.
    std::uint32_t listed[TowardLight::kMaxList];
    int nlisted = -1;
    if (skip != csg::kNone && !impl.toward_light.empty())
        if (const int k = impl.toward_light.light_of(ray.o, ray.d, ray.tfar, skip, impl.top.balls); k >= 0) {
            nlisted = impl.toward_light.list(k, skip, impl.top.balls, listed);
            scratch.counters.listed_shadows += nlisted >= 0;
            if (nlisted >= 0 && passes_clear(impl, ray, listed, nlisted)) return 0;
            for (int i = 0; i < nlisted; ++i)
                if (proves_blocked(impl, ray, listed[i])) return 1;
        }
    if (nlisted < 0 && scratch.blocker_owner == impl.id && scratch.blocker != skip &&
        proves_blocked(impl, ray, scratch.blocker))
        return 1;
    return bare_occluded_state(impl, ray, scratch, skip, listed, nlisted);
}

}  // namespace kerf::render
