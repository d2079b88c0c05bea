// The queries of a bare-sphere crowd's cone rays (bare_spheres.hpp). Each
// answers as CsgTracer::intersect / occluded do for the same ray: the same
// early out where the line misses `reach` (make_state's slab test), the
// same cone (ray_cone), its units in the same order with the same stop,
// and per unit the tests of bare_spheres.hpp; ties go by unit index
// (first_hit.cpp, take_entry). Only the set-up the general query makes
// for Embree (the float ray, the Embree context) is left out.
#include "render/tracer/bare_spheres.hpp"

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

int bare_occluded(const CsgTracer::Impl& impl, const TraceRay& ray, TraceScratch& scratch, std::uint32_t skip) {
    RayState st;
    if (!make_state(st, &impl, ray, scratch, false)) return 0;
    if (!impl.sphere_grid.empty()) return grid_occluded(st, ray, skip);
    const RayCone* cone = ray_cone(st, ray, false);
    if (!cone) return -1;
    // A point of the segment is within (tfar - t)·|d| + rho of the light.
    const double seg = (ray.tfar - ray.tnear) * st.len * (1 + 1e-9);
    for (const ConeUnit& u : cone->units) {
        if (u.key > seg) break;
        if (u.item != skip && bare_sphere_blocks(st, u.item, impl.top.items[u.item], ray.tnear, ray.tfar)) return 1;
    }
    return 0;
}

}  // namespace kerf::render
