// Ray cones (ray_cones.hpp; README.md, "Ray cones"): the apexes, built once
// with the tracer, and each thread's cones around them, built on first use.
//
// Exactness. A ray of apex p (its start within rho of p, for a camera; its
// end, for a light) whose direction lies within alpha of a cone's axis lies
// within rho of the cone (a cone is convex, and so is its rho-neighbourhood).
// Every point of a unit the ray's own tests keep (unit_ball_misses, the
// outer chord of ball_chords.hpp: the unit's ball grown by 4·eps_ray, the
// relative slack and the chord's 1e-13 term) lies within `radius` of the
// unit's centre, since those slacks grow with |c - o| and |o| and both are
// bounded by the apex's (o lies within rho, or within `reach`, of p); so a
// unit whose grown ball misses the cone grown by rho would be dropped by
// the ray anyway. The cone lists the units in the apex's order, so its rays
// visit the units they keep in the same order whatever cone (and thread)
// they meet: the same answers and the same work.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

double l1(const glm::dvec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// The cone of apex `a` around dir (away from the apex, |dir| = st.len),
// listed into `cone`.
void build_cone(const RayState& st, std::uint32_t a, const glm::dvec3& dir, RayCone& cone) {
    const Apex& ap = st.impl->apexes[a];
    cone.owner = st.impl->id;
    cone.apex = a;
    cone.axis = dir / glm::length(dir);
    cone.units.clear();
    cone.units.reserve(ap.order.size());  // once per slot and scene: no growth while listing
    // A ball meets the cone when the angle from the axis to its centre is
    // at most alpha plus its angular radius beta: cos(angle) >= cos(alpha +
    // beta) (alpha + beta < pi). The margin 1e-12 in the cosines is beyond
    // their round-off (~1e-16) and widens the angle by at least as much.
    for (std::size_t j = 0; j < ap.order.size(); ++j)
        if (glm::dot(ap.towards[j], cone.axis) >=
            ap.cos_alpha * ap.cos_beta[j] - ap.sin_alpha * ap.sin_beta[j] - 1e-12)
            cone.units.push_back({ap.order[j], ap.key[j]});
}

// The thread's cone of apex `a` holding dir, built (over the oldest) when
// none does.
const RayCone* find_cone(const RayState& st, std::uint32_t a, const glm::dvec3& dir) {
    RayCones& rc = st.scratch->cones;
    const double need = st.impl->apexes[a].cos_in * st.len;
    const auto holds = [&](const RayCone& c) {
        return c.owner == st.impl->id && c.apex == a && glm::dot(dir, c.axis) >= need;
    };
    int& last = rc.last[a];
    if (holds(rc.cones[last])) return &rc.cones[last];
    for (int i = 0; i < RayCones::kSlots; ++i)
        if (holds(rc.cones[i])) {
            last = i;
            return &rc.cones[i];
        }
    RayCone& c = rc.cones[rc.next];
    last = rc.next;
    rc.next = (rc.next + 1) % RayCones::kSlots;
    build_cone(st, a, dir, c);
    ++rc.built;
    return holds(c) ? &c : nullptr;  // (a zero direction: no cone)
}

}  // namespace

const RayCone* ray_cone_of_apex(const RayState& st, const TraceRay& ray, bool from) {
    const std::vector<Apex>& apexes = st.impl->apexes;
    for (std::uint32_t a = 0; a < apexes.size(); ++a) {
        const Apex& ap = apexes[a];
        if (ap.from != from) continue;
        if (from) {
            // o + t·d for t >= tnear >= 0 lies within |o - p| of p + t·d.
            if (ray.tnear >= 0 && l1(ray.o - ap.p) <= ap.rho) return find_cone(st, a, ray.d);
            continue;
        }
        // The segment is end - s·d for s in [0, tfar - tnear]; its end is
        // found to within `err`.
        if (!(ray.tfar < kInf) || !(ray.tnear <= ray.tfar)) continue;
        const glm::dvec3 end = ray.o + ray.tfar * ray.d;
        const double err = 1e-14 * (l1(ray.o) + ray.tfar * l1(ray.d));
        if (l1(end - ap.p) + err <= ap.rho && l1(ray.o - ap.p) <= ap.reach) return find_cone(st, a, -ray.d);
    }
    return nullptr;
}

void CsgTracer::Impl::build_apexes() {
    const std::size_t n = top.items.size();
    if (!top.bvh || n > kMaxConeUnits || top.balls.size() != n || !top.always.empty()) return;
    std::vector<double> radii;
    for (const Ball& b : top.balls) {
        if (!(b.r >= 0)) return;
        radii.push_back(b.r);
    }
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    const double r_mid = radii[radii.size() / 2];
    const glm::dvec3 mid = 0.5 * (reach.lo + reach.hi);
    const auto add = [&](const glm::dvec3& p, bool from) {
        Apex ap;
        ap.p = p;
        ap.from = from;
        const double p1 = l1(p), pf = l1(p - frame);
        // A shadow ray starts near a surface, within frame_radius (L2) of
        // the frame, so within 2·frame_radius in L1, and with the surface
        // offset far less than another 2.
        ap.reach = from ? 0 : pf + 4 * frame_radius;
        ap.rho = 1e-9 * (p1 + pf + frame_radius);
        // Half the middle ball's angular radius: a cone lists the units
        // around a ray and few more.
        ap.alpha = std::clamp(0.5 * r_mid / glm::length(mid - p), 1e-3, 0.25);
        if (!std::isfinite(ap.alpha)) ap.alpha = 0.25;
        ap.cos_in = std::cos(ap.alpha * (1 - 1e-6));
        // The per-ray slacks: 4·eps_ray, eps_ray <= eps_per_distance·|o|;
        // the ball slack and the chord's sqrt(1e-13) (< 3.2e-7) times
        // |c - o|_1 (+ r), |c - o|_1 <= |c - p|_1 + reach + rho.
        const double slack_abs = 4 * eps_per_distance * (p1 + ap.reach + ap.rho);
        const double rel = 2 * ball_slack + 1e-6;
        ap.cos_alpha = std::cos(ap.alpha);
        ap.sin_alpha = std::sin(ap.alpha);
        std::vector<double> key(n), radius(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Ball& b = top.balls[i];
            // The ball, grown by those slacks and by rho: the ray lies within
            // rho of its cone.
            radius[i] = grown_radius(b.r, slack_abs, rel, l1(b.c - p) + ap.reach + ap.rho + b.r) + ap.rho;
            key[i] = glm::length(b.c - p) - radius[i];
        }
        ap.order.resize(n);
        std::iota(ap.order.begin(), ap.order.end(), 0u);
        std::sort(ap.order.begin(), ap.order.end(),
                  [&](std::uint32_t x, std::uint32_t y) { return key[x] < key[y] || (key[x] == key[y] && x < y); });
        for (std::uint32_t i : ap.order) {
            ap.key.push_back(key[i]);
            const glm::dvec3 w = top.balls[i].c - p;
            const double dw = glm::length(w);
            const bool inside = !(dw > radius[i] * (1 + 1e-9));
            ap.towards.push_back(inside ? glm::dvec3(0.0) : w / dw);
            const double s = inside ? 0 : radius[i] / dw;
            ap.cos_beta.push_back(inside ? -2 : std::sqrt(1 - s * s));
            ap.sin_beta.push_back(s);
        }
        apexes.push_back(std::move(ap));
    };
    const csg::Camera& cam = scene.camera;
    if (cam.projection == csg::Projection::Planar && !cam.orthographic && !(cam.aperture > 0)) add(cam.position, true);
    for (const csg::Light& light : scene.lights)
        if (!light.directional && light.shadows && apexes.size() < RayCones::kApexes) add(light.position, false);
}

}  // namespace kerf::render
