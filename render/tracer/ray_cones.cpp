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

// A lower bound on the distance from the apex of the points of the unit's
// grown ball that lie in the cone of half-angle alpha around `axis` (a ray
// of the cone keeps no point of the unit nearer the apex: see Apex::key):
// at least the ball's own key, and, when the ball's centre lies at an angle
// theta > alpha off the axis, where a direction phi = theta - alpha off the
// centre's enters it (the nearest of the cone's directions to the centre;
// the entry D·cos(phi) - sqrt(R² - D²·sin²(phi)) grows with phi up to the
// tangent angle beta, where it stops). In a narrow cone of a crowd of balls
// large against it, this orders the units nearly as its rays enter them,
// and the loop's stop comes before units that lie beside the cone.
// Round-off: alpha is taken 1e-6 wider (Apex::cos_key; sin(theta) from the
// cosine is good to 1e-13 where theta > alpha >= 1e-3), the square root's
// argument grows by 1e-12·D² (its cancellation near the tangent), and the
// whole is lowered by 1e-9·D.
double cone_key(const Apex& ap, int level, const ConeUnit& u, const glm::dvec3& axis) {
    const double c = std::clamp(glm::dot(ap.towards[u.j], axis), -1.0, 1.0);
    const double ca = ap.cos_key[level], sa = ap.sin_key[level];
    if (ap.cos_beta[u.j] < -1 || c >= ca) return u.key;  // the apex in the ball, or theta <= alpha
    const double st = std::sqrt(1 - c * c), d = ap.dist[u.j], s = ap.sin_beta[u.j];
    double cp = c * ca + st * sa, sp = st * ca - c * sa;  // phi = theta - alpha
    if (!(sp < s && cp > 0)) {
        cp = ap.cos_beta[u.j];  // past the tangent: phi = beta
        sp = s;
    }
    const double r = s * d, q = d * sp;
    const double entry = d * cp - std::sqrt(std::max(0.0, r * r - q * q) + 1e-12 * d * d) - 1e-9 * d;
    return std::max(u.key, entry);
}

// Crowds whose balls span orders of magnitude (spiral_1000: 0.979^k):
// the radius that half the sum of the radii comes from balls at least as
// large. The middle ball would set the cones' angle by the many tiny balls
// few rays meet; this one by the balls most rays do meet (spiral_1000 at
// 1024²: 1,383 → 1,061 M instructions with this alone; at 0.2, 0.35, 0.3
// or 0.7 of the sum worse on spiral_1000 or spiral_10000).
double spread_radius(const std::vector<double>& sorted_radii) {
    double total = 0, acc = 0;
    for (double r : sorted_radii) total += r;
    for (std::size_t i = sorted_radii.size(); i-- > 0;)
        if ((acc += sorted_radii[i]) >= 0.5 * total) return sorted_radii[i];
    return sorted_radii[0];
}

// A cone that would list more than its apex's max_units: emptied and
// marked, so that its rays take the ball or box BVH (ray_cone_around), and
// the narrow cones of a full wide cone are full too. Whether a cone is full
// depends on its cell alone, so a ray's path (and work) still does.
void publish(const RayState& st, RayCone& cone) { cone.owner = st.impl->id; }
void mark_full(const RayState& st, RayCone& cone) {
    cone.units.clear();
    cone.full = true;
    publish(st, cone);
}

// The cone of apex `a` and `level` around `axis` (unit, away from the
// apex), listed into `cone` from `from` (the units of a wider cone that
// holds it) or, with none, from every unit.
void build_cone(const RayState& st, std::uint32_t a, int level, const glm::dvec3& axis, const RayCone* from,
                RayCone& cone) {
    const Apex& ap = st.impl->apexes[a];
    // Claimed last (publish): a listing that fails (bad_alloc) leaves a
    // slot that names no tracer, never one holding another cell's units.
    cone.owner = 0;
    cone.apex = a;
    cone.level = level;
    cone.axis = axis;
    cone.units.clear();
    cone.full = from && from->full;
    if (cone.full) return publish(st, cone);
    // Listed into the thread's one scratch list, then copied at its size:
    // a slot reserving room for every unit (4,096 to 65,536 of them) would
    // hold up to 1 MB of address space each, 512 slots per thread.
    std::vector<ConeUnit>& list = st.scratch->cones.listing;
    list.clear();
    list.reserve(from ? from->units.size() : ap.order.size());  // no growth while listing
    // A ball meets the cone when the angle from the axis to its centre is
    // at most alpha plus its angular radius beta: cos(angle) >= cos(alpha +
    // beta) (alpha + beta < pi). The margin 1e-12 in the cosines is beyond
    // their round-off (~1e-16) and widens the angle by at least as much.
    const double ca = ap.cos_alpha[level], sa = ap.sin_alpha[level];
    const auto meets = [&](std::uint32_t j) {
        return glm::dot(ap.towards[j], cone.axis) >= ca * ap.cos_beta[j] - sa * ap.sin_beta[j] - 1e-12;
    };
    if (from) {
        // A ball the wider cone left out misses it, so this one too (it lies
        // in the wider cone: find_cone). Keyed by the cone's own bound.
        for (const ConeUnit& u : from->units)
            if (meets(u.j)) list.push_back({u.item, u.j, cone_key(ap, level, u, cone.axis)});
        if (list.size() > ap.max_units[level]) return mark_full(st, cone);
        std::sort(list.begin(), list.end(), [](const ConeUnit& x, const ConeUnit& y) {
            return x.key < y.key || (x.key == y.key && x.j < y.j);
        });
    } else {
        for (std::uint32_t j = 0; j < ap.order.size(); ++j)
            if (meets(j)) list.push_back({ap.order[j], j, ap.key[j]});
        if (list.size() > ap.max_units[level]) return mark_full(st, cone);
    }
    cone.units.assign(list.begin(), list.end());
    publish(st, cone);
}

// The thread's cone of apex `a` and `level` whose axis lies within the angle
// of cosine `need` of dir (|dir| = len), built (over the oldest of that
// level) when none does (one level).
[[gnu::noinline]] const RayCone* find_cone(const RayState& st, std::uint32_t a, const glm::dvec3& dir, double need) {
    RayCones& rc = st.scratch->cones;
    const double need_len = need * st.len;
    const auto holds = [&](const RayCone& c) {
        return c.owner == st.impl->id && c.apex == a && glm::dot(dir, c.axis) >= need_len;
    };
    RayCone* cones = rc.cones[0];
    int& last = rc.last[0][a];
    if (holds(cones[last])) return &cones[last];
    for (int i = 0; i < RayCones::kScan; ++i)
        if (holds(cones[i])) {
            last = i;
            return &cones[i];
        }
    int& next = rc.next[0];
    RayCone& c = cones[next];
    last = next;
    next = (next + 1) % RayCones::kScan;
    build_cone(st, a, 0, dir / glm::length(dir), nullptr, c);
    ++rc.built;
    return holds(c) ? &c : nullptr;  // (a zero direction: no cone)
}

// floor(x) for |x| < 1e9, without a library call.
std::int64_t floor_int(double x) {
    const std::int64_t i = std::int64_t(x);
    return double(i) > x ? i - 1 : i;
}

// The slot of cell (u, v) of apex a's grid (RayCones): neighbouring cells
// never share one, and a 16×16 patch of them stays.
int cell_slot(std::uint32_t a, std::int64_t u, std::int64_t v) {
    return int((std::uint64_t(u) & 15) | (std::uint64_t(v) & 15) << 4 | std::uint64_t(a & 1) << 8);
}

// Two levels: the cone of `level` serving direction dir (|dir| = len) is
// the one around the centre of dir's cell in a grid of the apex's gnomonic
// plane, whose cells' corners lie within the level's reach of their centres
// (a plane distance is at least the angle), checked with `need`: so
// neighbouring rays share cones that tile the directions, and a ray's cone
// (and with it the order its units are met in, and the work) depends on the
// ray alone, never on which cones the thread built before. Null when dir
// lies far off the plane's centre (or behind it): then the ray takes the
// ball BVH. A narrow cone is listed from the wide cone of its axis' cell
// (it lies in that one: find_cone's need for level 0 is cos_sub).
inline const RayCone* find_cell_cone(const RayState& st, std::uint32_t a, int level, const glm::dvec3& dir,
                                     double len, double need);

// find_cell_cone's cell (u, v) not kept in its slot `c`: built there (out of
// line: the kept cone, most rays' case, then needs no frame).
[[gnu::noinline]] const RayCone* build_cell_cone(const RayState& st, std::uint32_t a, int level,
                                                 const glm::dvec3& dir, double len, double need, std::int64_t u,
                                                 std::int64_t v, RayCone& c) {
    const Apex& ap = st.impl->apexes[a];
    const double g = ap.grid[level];
    const glm::dvec3 axis = glm::normalize(ap.e0 + ((double(u) + 0.5) * g) * ap.e1 + ((double(v) + 0.5) * g) * ap.e2);
    if (!(glm::dot(dir, axis) >= need * len)) return nullptr;
    const RayCone* from = level > 0 ? find_cell_cone(st, a, level - 1, axis, 1, ap.cos_sub[level]) : nullptr;
    if (level > 0 && !from) return nullptr;
    c.owner = 0;  // (build_cone claims it once listed)
    c.u = u;
    c.v = v;
    build_cone(st, a, level, axis, from, c);
    ++st.scratch->cones.built;
    return &c;
}

inline const RayCone* find_cell_cone(const RayState& st, std::uint32_t a, int level, const glm::dvec3& dir,
                                     double len, double need) {
    const Apex& ap = st.impl->apexes[a];
    const double w = glm::dot(dir, ap.e0), g = ap.grid[level];
    if (!(w > 0.5 * len)) return nullptr;
    const double inv = 1 / (w * g), x = glm::dot(dir, ap.e1) * inv, y = glm::dot(dir, ap.e2) * inv;
    if (!(std::abs(x) < 1e9 && std::abs(y) < 1e9)) return nullptr;
    const std::int64_t u = floor_int(x), v = floor_int(y);
    // The cone of the apex's last ray at the rays' level first: the same
    // slot when its cell is this one (a cell's cone lives only in its own
    // slot), found by a branch the next rays of a row predict, so that the
    // loop over its units need not wait for the division and the floors
    // that name the slot.
    RayCones& rc = st.scratch->cones;
    const bool memo = level == Apex::kLevels - 1 && a < RayCones::kApexes;
    const RayCone* kept = memo && rc.last_cell[a] ? &rc.cones[level][rc.last_cell[a] - 1] : nullptr;
    if (kept && kept->owner == st.impl->id && kept->apex == a && kept->u == u && kept->v == v)
        return glm::dot(dir, kept->axis) >= need * len ? kept : nullptr;
    const int slot = cell_slot(a, u, v);
    RayCone& c = rc.cones[level][slot];
    // A kept cone answers as a new one would (the same direction test), so
    // whether a ray takes a cone never depends on the thread's history.
    if (memo) rc.last_cell[a] = std::uint16_t(slot + 1);
    if (c.owner == st.impl->id && c.apex == a && c.u == u && c.v == v)
        return glm::dot(dir, c.axis) >= need * len ? &c : nullptr;
    return build_cell_cone(st, a, level, dir, len, need, u, v, c);
}

// The cone of the apex's finest level holding a ray of direction dir.
[[gnu::always_inline]] inline const RayCone* ray_cone_around(const RayState& st, std::uint32_t a, const glm::dvec3& dir) {
    const Apex& ap = st.impl->apexes[a];
    if (ap.levels == 1) return find_cone(st, a, dir, ap.cos_in[0]);
    const RayCone* c = find_cell_cone(st, a, ap.levels - 1, dir, st.len, ap.cos_in[ap.levels - 1]);
    return c && !c->full ? c : nullptr;
}

}  // namespace

const RayCone* ray_cone_of_apex(const RayState& st, const TraceRay& ray, bool from) {
    const std::vector<Apex>& apexes = st.impl->apexes;
    for (std::uint32_t a = 0; a < apexes.size(); ++a) {
        const Apex& ap = apexes[a];
        if (ap.from != from) continue;
        if (from) {
            // o + t·d for t >= tnear >= 0 lies within |o - p| of p + t·d.
            if (ray.tnear >= 0 && l1(ray.o - ap.p) <= ap.rho) return ray_cone_around(st, a, ray.d);
            continue;
        }
        // The segment is end - s·d for s in [0, tfar - tnear]; its end is
        // found to within `err`.
        if (!(ray.tfar < kInf) || !(ray.tnear <= ray.tfar)) continue;
        const glm::dvec3 end = ray.o + ray.tfar * ray.d;
        const double err = 1e-14 * (l1(ray.o) + ray.tfar * l1(ray.d));
        if (l1(end - ap.p) + err <= ap.rho && l1(ray.o - ap.p) <= ap.reach) return ray_cone_around(st, a, -ray.d);
    }
    return nullptr;
}

void CsgTracer::Impl::build_apexes() {
    const std::size_t n = top.items.size();
    if (!top.bvh || n > kMaxSpreadUnits || top.balls.size() != n || !top.always.empty()) return;
    std::vector<double> radii;
    for (const Ball& b : top.balls) {
        if (!(b.r >= 0)) return;
        radii.push_back(b.r);
    }
    std::sort(radii.begin(), radii.end());
    const double r_mid = radii[radii.size() / 2];
    // Two levels only for balls of about one size: the cones' angle follows
    // the middle ball, and a crowd whose balls span orders of magnitude
    // (spiral_1000: 0.979^k, its middle ball 2e-5 of the largest) lists
    // the large ones in a great many narrow cones (427 → 599 M instructions
    // at 512²; cells_1000's radii span 6.7×). Such crowds (up to
    // kMaxSpreadUnits) take their angle from spread_radius instead, and
    // cones too full fall back to the BVH (Apex::max_units).
    const bool spread = n > kMaxConeUnits && radii[n - 1 - n / 10] > 10 * radii[n / 10];
    if (!spread && n > kMaxTwoLevelUnits) return;
    const double r_cone = spread ? spread_radius(radii) : r_mid;
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
        // around a ray and few more. Two levels: the rays' cones a quarter
        // of it (their keys order the units as the rays enter them, so the
        // loop stops sooner; narrower cones cost more listings than they
        // save: cells_1000 at 512², 0.125 / 0.18 / 0.25 / 0.5 / 1 gave
        // 787 / 653 / 629 / 687 / 854 M instructions, base 778 M), the wide
        // ones 8 times that (4 / 8 / 12 / 16: 695 / 629 / 636 / 699 M at 0.25
        // before the grid; shell_1000 and cells_2000 agree).
        ap.levels = n > kMaxConeUnits ? 2 : 1;
        if (spread) {
            // Where many tiny balls crowd one direction (the spiral's
            // centre: 9,000 units within 2e-9 of it in spiral_10000) a cone
            // would list them all and its rays visit them one by one; the
            // BVH passes them in a few boxes. (spiral_10000 at 1024²: 2,260
            // M instructions with no limit, 1,784 M with these; 256 / 4,096
            // and 32 / 128 measured within 0.1 % on spiral_10000, 256 wide
            // 7 % worse on spiral_1000.)
            ap.max_units[0] = kSpreadWideUnits;
            ap.max_units[1] = kSpreadNarrowUnits;
        }
        double alpha = std::clamp((ap.levels > 1 ? 0.25 : 0.5) * r_cone / glm::length(mid - p), 1e-3, 0.25);
        if (!std::isfinite(alpha)) alpha = 0.25;
        for (int l = ap.levels - 1; l >= 0; --l, alpha = std::min(alpha * 8, 1.0)) {
            ap.alpha[l] = alpha;
            ap.cos_in[l] = std::cos(alpha * (1 - 1e-6));
            ap.cos_alpha[l] = std::cos(alpha);
            ap.sin_alpha[l] = std::sin(alpha);
            ap.cos_key[l] = std::cos(alpha + 1e-6);
            ap.sin_key[l] = std::sin(alpha + 1e-6);
            // A cone of this level must hold a ray within alpha of its axis,
            // or a narrower cone's axis within alpha less that one's alpha.
            const double reach = l + 1 < ap.levels ? alpha - ap.alpha[l + 1] : alpha;
            if (l + 1 < ap.levels) ap.cos_sub[l + 1] = std::cos(reach * (1 - 1e-6));
            ap.grid[l] = ap.levels > 1 ? 0.999 * reach * std::sqrt(2.0) : 0;
        }
        ap.e0 = glm::normalize(mid - p);
        if (!(glm::length(ap.e0) > 0.5)) ap.e0 = glm::dvec3(0, 0, 1);
        ap.e1 = glm::normalize(glm::cross(ap.e0, std::abs(ap.e0.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
        ap.e2 = glm::cross(ap.e0, ap.e1);
        // The per-ray slacks: 4·eps_ray, eps_ray <= eps_per_distance·|o|;
        // the ball slack and the chord's sqrt(1e-13) (< 3.2e-7) times
        // |c - o|_1 (+ r), |c - o|_1 <= |c - p|_1 + reach + rho.
        const double slack_abs = 4 * eps_per_distance * (p1 + ap.reach + ap.rho);
        const double rel = 2 * ball_slack + 1e-6;
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
            ap.dist.push_back(dw);
            if (from) {
                // outer_chord_reaches' terms for a ray whose origin is p
                // (make_state's eps_ray for that origin).
                const double w1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
                const double rr = grown_radius(top.balls[i].r, 4 * (eps_per_distance * glm::length(p)), ball_slack, w1);
                ap.at_p.push_back({w, w1, rr * rr, 1e-13 * (w1 * w1 + rr * rr)});
            }
        }
        apexes.push_back(std::move(ap));
    };
    const csg::Camera& cam = scene.camera;
    if (cam.projection == csg::Projection::Planar && !cam.orthographic && !(cam.aperture > 0)) add(cam.position, true);
    for (const csg::Light& light : scene.lights)
        if (!light.directional && light.shadows && apexes.size() < RayCones::kApexes) add(light.position, false);
}

}  // namespace kerf::render
