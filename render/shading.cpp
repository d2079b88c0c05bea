#include "render/shading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/ao.hpp"
#include "render/ground.hpp"
#include "render/lights.hpp"
#include "render/optics.hpp"
#include "render/patterns.hpp"

namespace kerf::render {

namespace {
constexpr double kAmbient = 0.1;  // POV-Ray's default ambient: shadows are not pitch black

// (n·h)^s for the Blinn–Phong highlight, from x2 = (n·h)² (docs/quality.md,
// "Shading's rounding"): the half vector need not be normalised, which
// took a square root and three divisions per lit shading point, sharing
// the divider with the normal's and the shadow ray's;
// (n·h')²/(h'·h') is one division. Whole exponents (the
// usual 8..256) by repeated squaring of x2, a few multiplies (an odd one
// takes one square root); others by pow. In [0, 1024] the truncating
// conversion is the floor, two instructions where std::floor is a libm
// call (no SSE4.1).
[[gnu::always_inline]] inline double highlight(double x2, double s) {
    if (s >= 0 && s <= 1024 && s == double(unsigned(s))) {
        unsigned e = unsigned(s);
        double r = e & 1 ? std::sqrt(x2) : 1, base = x2;
        for (e >>= 1; e != 0; e >>= 1) {
            if (e & 1) r *= base;
            base *= base;
        }
        return r;
    }
    return std::pow(x2, 0.5 * s);
}
}  // namespace

Shader::Shader(const csg::Scene& scene, const CsgTracer& tracer, int max_depth, bool ground)
    : scene_(scene), tracer_(tracer), max_depth_(max_depth), miss_(scene.fog.on() ? scene.fog.color : scene.background),
      ground_(ground && scene.ground.on) {
    // Far above the round-off of a point on the plane, far below the solid's size.
    const csg::Aabb box = scene.bounds();
    ground_lift_ = ground_ ? 1e-7 * glm::length(box.hi - box.lo) + 1e-12 * glm::length(0.5 * (box.lo + box.hi)) : 0;
    if (ground_) ground_shadow_ = ground_shadow_box(scene);
    for (csg::Light l : scene.lights) {
        l.direction = glm::normalize(l.direction);  // once, not per shading point
        lights_.push_back(l);
        patterns_.emplace_back(int(l.samples));
    }
    for (const csg::Material& m : scene.materials) any_transparent_ |= m.transparency > 0;
    one_point_light_ = lights_.size() == 1 && !lights_[0].directional && !(lights_[0].radius > 0) &&
                       !(scene.ambient_occlusion.samples > 0);
}

const csg::Material& Shader::material_of(std::uint32_t leaf) const { return leaf_material(scene_, leaf); }

glm::dvec3 Shader::through_glass(const TraceRay& ray, ThreadState& ts) const {
    tracer_.inside_spans(ray, ts.scratch, ts.spans);
    glm::dvec3 k(1.0);
    const double len = glm::length(ray.d);
    for (const Span& sp : ts.spans) {
        const csg::Material& m = material_of(sp.e0.mat_leaf);
        if (m.transparency <= 0) return glm::dvec3(0.0);
        k *= m.transparency * beer_lambert(m.absorption, (sp.t1 - sp.t0) * len);
    }
    return k;
}

// The mirror ray's radiance; a rough surface averages rays spread over a
// cone round it (half-angle roughness·45°), 8 at the first bounce and 1
// deeper, seeded by the shading point so pixels do not depend on threads.
glm::dvec3 Shader::mirror(const glm::dvec3& origin, const glm::dvec3& r, const glm::dvec3& n, double roughness,
                          int depth, ThreadState& ts) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (roughness <= 0) {
        ++ts.rays.reflect;
        return radiance(TraceRay{origin, r, 0, inf}, depth + 1, ts);
    }
    const int count = depth == 0 ? 8 : 1;
    const SamplePattern pattern(count);
    std::uint64_t rng = shading_rng(origin, 0x6C6F7373);  // "loss": a stream apart from the lights'
    // A cone of half-angle θ round r is the cone a sphere of radius sin θ at
    // distance 1 fills: reuse the soft lights' uniform cone sampling.
    const ConeBasis cone(glm::normalize(r), 1, std::sin(roughness * M_PI / 4));
    glm::dvec3 sum(0.0);
    for (int i = 0; i < count; ++i) {
        double reach;
        glm::dvec3 dir = cone.direction(pattern.offset(i, rng), reach);
        if (glm::dot(dir, n) <= 0) dir = mirror_direction(dir, n);  // keep it above the surface
        ++ts.rays.reflect;
        sum += radiance(TraceRay{origin, dir, 0, inf}, depth + 1, ts);
    }
    return sum / double(count);
}

glm::dvec3 Shader::inside(const glm::dvec3& p, const glm::dvec3& d, const csg::Material& m, double tol, int depth,
                          ThreadState& ts) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    ++ts.rays.refract;
    tracer_.inside_spans(TraceRay{p, d, 0, inf}, ts.scratch, ts.spans);
    const Span* exit = nullptr;
    for (const Span& sp : ts.spans)
        if (sp.t1 > tol) {
            exit = &sp;
            break;
        }
    // Grazing round-off: the ray is not inside after all; go on outside.
    if (!exit || exit->t0 > tol) return radiance(TraceRay{p, d, tol, inf}, depth, ts);
    const double t1 = exit->t1;
    // An unbounded solid (a half-space in the union) the ray never leaves:
    // it runs off to infinity inside, a miss seen through all that glass
    // (its exit point would be at infinity, no ray to trace from there).
    if (!(t1 < inf)) return beer_lambert(m.absorption, inf) * missed(TraceRay{p, d, tol, inf}, ts);
    const TraceHit hit{t1, exit->e1};
    const glm::dvec3 q = p + t1 * d;
    const glm::dvec3 absorbed = beer_lambert(m.absorption, t1);
    // The normal facing the arriving ray, i.e. into the solid: orientation
    // from the ray, so a CSG exit (a subtrahend's flipped face) is right too.
    glm::dvec3 n = tracer_.normal(hit, q);
    if (glm::dot(n, d) > 0) n = -n;
    const double off = tracer_.surface_offset(hit, q);
    const double cos_i = -glm::dot(d, n);
    double cos_t;
    const double f = fresnel_dielectric(cos_i, m.ior, cos_t);
    glm::dvec3 c(0.0);
    if (f < 1) c += (1 - f) * radiance(TraceRay{q - off * n, refract_direction(d, n, m.ior, cos_i, cos_t), 0, inf}, depth, ts);
    if (f > 1e-9 && depth < max_depth_) c += f * inside(q, mirror_direction(d, n), m, off, depth + 1, ts);
    return absorbed * c;
}

glm::dvec3 Shader::missed(const TraceRay& ray, ThreadState& ts) const {
    if (ground_) {
        const double t = ground_distance(scene_.ground, ray);
        if (t < ray.tfar) return ground(ray.o + t * ray.d, ts);
    }
    return miss_;
}

// In front of the solid, the ground: a miss that may be in shadow (the
// same surface id as a miss: the shadow's edge is refined by its colour,
// not a seam along the horizon).
bool Shader::ground_first(const TraceRay& ray, bool solid, const TraceHit& hit, double& t) const {
    if (!ground_) return false;
    t = ground_distance(scene_.ground, ray);
    return t < (solid ? hit.t : ray.tfar);
}

namespace {
std::uint32_t surface_id(const TraceHit& hit) { return (hit.surface.leaf + 1) * 2 + hit.surface.cut; }
}  // namespace

std::uint32_t Shader::surface(const TraceRay& ray, ThreadState& ts) const {
    TraceHit hit;
    const bool solid = tracer_.intersect(ray, hit, ts.scratch);
    double t;
    if (ground_first(ray, solid, hit, t) || !solid) return 0;
    ts.hit = hit;
    return surface_id(hit);
}

glm::dvec3 Shader::radiance(const TraceRay& ray, bool solid, const TraceHit& hit, int depth, ThreadState& ts,
                            std::uint32_t* surface) const {
    double t;
    if (ground_first(ray, solid, hit, t)) {
        if (surface) {
            *surface = 0;
            ts.on_ground = true;
        }
        return ground(ray.o + t * ray.d, ts);
    }
    if (!solid) {
        if (surface) *surface = 0;
        return miss_;  // fog: as if at infinite distance, all fog
    }
    if (surface) *surface = surface_id(hit), ts.hit = hit;
    if (!scene_.fog.on()) return shade(ray, hit, depth, ts);  // a tail call: no frame kept round it
    return fogged(shade(ray, hit, depth, ts), hit.t * glm::length(ray.d));
}

// `c` seen through fog over distance `dist` (ray.d need not be unit, as for
// primary rays: the distance is t·|d|). Out of line: rare, and kept out of
// radiance()'s frame.
glm::dvec3 Shader::fogged(const glm::dvec3& c, double dist) const {
    const double keep = std::exp(-dist / scene_.fog.distance);
    return keep * c + (1 - keep) * scene_.fog.color;
}

template <class Ray>
void Shader::light_rays(const glm::dvec3& origin, const glm::dvec3& n, const Departure* from, ThreadState& ts,
                        Ray&& ray) const {
    for (std::size_t li = 0; li < lights_.size(); ++li) {
        const csg::Light& light = lights_[li];
        LightView view;
        if (!view_light(light, origin, view)) continue;
        const glm::dvec3& l = view.l;
        const double dist = view.dist, k = view.k;
        if (light.radius <= 0 || dist <= light.radius) {
            const double ndl = glm::dot(n, l);
            if (ndl <= 0) continue;
            ray(light, l, ndl, light.color * k, light.shadows ? transmitted(TraceRay{origin, l, 0, dist}, ts, from) : glm::dvec3(1.0));
            continue;
        }
        sphere_rays(li, view, origin, n, from, ts, ray);
    }
}

// A sphere: the mean response over stratified directions into the cone it
// fills, each with its own shadow ray (soft shadows). Out of line: the
// plain point light's path in shade() keeps its registers.
template <class Ray>
void Shader::sphere_rays(std::size_t li, const LightView& view, const glm::dvec3& origin, const glm::dvec3& n,
                         const Departure* from, ThreadState& ts, Ray& ray) const {
    const csg::Light& light = lights_[li];
    const ConeBasis cone(view.l, view.dist, light.radius);
    const SamplePattern& pattern = light.probe && ts.refining ? refining_ : patterns_[li];
    std::uint64_t rng = shading_rng(origin, li);
    const glm::dvec3 share = light.color * (view.k / double(pattern.count()));
    if (light.probe && light.shadows && !ts.refining)
        return probed_rays(light, cone, pattern, rng, origin, n, share, from, ts, ray);
    for (int i = 0; i < pattern.count(); ++i) {
        double reach;
        const glm::dvec3 dir = cone.direction(pattern.offset(i, rng), reach);
        const double ndl = glm::dot(n, dir);
        if (ndl <= 0) continue;
        ray(light, dir, ndl, share, light.shadows ? transmitted(TraceRay{origin, dir, 0, reach}, ts, from) : glm::dvec3(1.0));
    }
}

// The `samples` directions are the plain light's (same generator, same
// order), so where the probes disagree the result is the plain light's to
// the bit. Four probes go to the cone's rim, a quarter turn apart (turned
// by a stream of their own): a straight shadow edge that crosses the light
// without separating them cuts off at most the segment between two, 9 % of
// the disc; the fifth, to its centre, catches light through a hole. Where
// all five face the surface and let the same light through, so are the
// samples taken to: exact in full light and full shadow, a bias only where
// a shadow's edge slips between the probes (quality.md).
template <class Ray>
void Shader::probed_rays(const csg::Light& light, const ConeBasis& cone, const SamplePattern& pattern,
                         std::uint64_t& rng, const glm::dvec3& origin, const glm::dvec3& n, const glm::dvec3& share,
                         const Departure* from, ThreadState& ts, Ray&& ray) const {
    std::uint64_t turn_rng = rng ^ 0x70726F62;  // "prob"
    const double turn = uniform01(turn_rng);
    glm::dvec3 through[5];
    bool agree = true;
    for (int j = 0; j < 5 && agree; ++j) {
        double reach;
        const glm::dvec3 dir = cone.direction({j < 4 ? 1.0 : 0.0, (j + turn) / 4}, reach);
        agree = glm::dot(n, dir) > 0;  // else the terminator: trace them all
        if (agree) through[j] = transmitted(TraceRay{origin, dir, 0, reach}, ts, from);
        agree = agree && through[j] == through[0];
    }
    for (int i = 0; i < pattern.count(); ++i) {
        double reach;
        const glm::dvec3 dir = cone.direction(pattern.offset(i, rng), reach);
        const double ndl = glm::dot(n, dir);
        if (ndl <= 0) continue;
        ray(light, dir, ndl, share, agree ? through[0] : transmitted(TraceRay{origin, dir, 0, reach}, ts, from));
    }
}

glm::dvec3 Shader::ground(const glm::dvec3& p, ThreadState& ts) const {
    // Most of the ground is where no shadow can fall: no shadow rays there.
    if (!(p.x >= ground_shadow_.lo.x && p.x <= ground_shadow_.hi.x && p.y >= ground_shadow_.lo.y &&
          p.y <= ground_shadow_.hi.y))
        return miss_;
    const glm::dvec3 up(0, 0, 1);
    double all = 0, blocked = 0;  // the shadow-casting lights' light reaching p: unblocked, blocked
    light_rays(p + ground_lift_ * up, up, nullptr, ts, [&](const csg::Light& light, const glm::dvec3&, double ndl, const glm::dvec3& k, const glm::dvec3& through) {
        if (!light.shadows) return;
        const double w = ndl * (k.r + k.g + k.b);
        all += w;
        blocked += w * (1 - (through.r + through.g + through.b) / 3);
    });
    // Nothing blocked: exactly the miss colour, as a culled tile gives.
    if (!(blocked > 0) || !(all > 0)) return miss_;
    return miss_ * (1 - scene_.ground.shadow * std::min(1.0, blocked / all));
}

namespace {

// The surface's response to light of colour `k` arriving from unit
// direction l, with h = |d|·l − d the half vector (not normalised), added
// to the diffuse and highlight sums: one copy for both shading paths, so
// shade_point_lit keeps shade_any's bits. Inlined: a call per light per
// shading point spilled its arguments and returned through memory.
[[gnu::always_inline]] inline void respond(const csg::Material& m, const glm::dvec3& n, const glm::dvec3& albedo,
                                           const glm::dvec3& h, double ndl, const glm::dvec3& k,
                                           glm::dvec3& diffuse, glm::dvec3& highlights) {
    const double nh = glm::dot(n, h);
    diffuse += k * (m.diffuse * ndl) * albedo;
    highlights += k * (m.specular * highlight(nh > 0 ? nh * nh / glm::dot(h, h) : 0.0, m.shininess));
}

}  // namespace

// Most scenes' case (the bench's: one point light, opaque materials): the
// general path's numbers in its order, without its loop over lights and
// its lambdas' captures, the ambient occlusion and mirror branches, and
// the Departure (a call) where no shadow ray goes: ~25 % of its
// instructions per hit.
glm::dvec3 Shader::shade_point_lit(const TraceRay& ray, const TraceHit& hit, const csg::Material& m,
                                   ThreadState& ts) const {
    const glm::dvec3 p = ray.o + hit.t * ray.d;
    glm::dvec3 n = tracer_.normal(hit, p);
    const bool facing = glm::dot(n, ray.d) <= 0;
    if (!facing) n = -n;
    const glm::dvec3 albedo = surface_albedo(scene_, m, hit.surface.mat_leaf, hit.surface.cut, p);
    const double off = tracer_.surface_offset(hit, p);
    const glm::dvec3 origin = p + off * n;
    glm::dvec3 diffuse(0.0), highlights(0.0);
    const csg::Light& light = lights_[0];
    LightView view;
    if (view_light(light, origin, view)) {
        const double ndl = glm::dot(n, view.l);
        if (ndl > 0) {
            const Departure from = facing ? tracer_.departure(hit, n) : Departure{};
            const glm::dvec3 through =
                light.shadows ? transmitted(TraceRay{origin, view.l, 0, view.dist}, ts, &from) : glm::dvec3(1.0);
            if (through != glm::dvec3(0.0))
                respond(m, n, albedo, glm::length(ray.d) * view.l - ray.d, ndl, light.color * view.k * through, diffuse,
                        highlights);
        }
    }
    // (kAmbient·open with open = 1 is kAmbient.)
    const glm::dvec3 local = kAmbient * albedo + diffuse + highlights;
    return local + m.emission;
}

glm::dvec3 Shader::shade(const TraceRay& ray, const TraceHit& hit, int depth, ThreadState& ts) const {
    if (one_point_light_) {
        const csg::Material& m = material_of(hit.surface.mat_leaf);
        if ((m.transparency == 0 && m.reflect == 0) || depth >= max_depth_) return shade_point_lit(ray, hit, m, ts);
    }
    return shade_any(ray, hit, depth, ts);
}

glm::dvec3 Shader::shade_any(const TraceRay& ray, const TraceHit& hit, int depth, ThreadState& ts) const {
    const glm::dvec3 p = ray.o + hit.t * ray.d;
    glm::dvec3 n = tracer_.normal(hit, p);
    const bool facing = glm::dot(n, ray.d) <= 0;
    if (!facing) n = -n;  // grazing round-off: light the side we see
    const csg::Material& m = material_of(hit.surface.mat_leaf);
    const glm::dvec3 albedo = surface_albedo(scene_, m, hit.surface.mat_leaf, hit.surface.cut, p);
    const double off = tracer_.surface_offset(hit, p);
    const glm::dvec3 origin = p + off * n;
    // |d|·l − d is the half vector between l and the view, |d|·(l + view),
    // without the view's three divisions (the highlight needs no length).
    const double dlen = glm::length(ray.d);

    glm::dvec3 diffuse(0.0), highlights(0.0);
    // Shadow rays leave the surface outwards only where n was not turned.
    const Departure from = facing ? tracer_.departure(hit, n) : Departure{};
    light_rays(origin, n, &from, ts, [&](const csg::Light&, const glm::dvec3& l, double ndl, const glm::dvec3& k, const glm::dvec3& through) __attribute__((always_inline)) {
        if (through != glm::dvec3(0.0))
            respond(m, n, albedo, dlen * l - ray.d, ndl, k * through, diffuse, highlights);
    });
    double open = 1;  // ambient occlusion: the ambient light's share that reaches p
    if (const csg::AmbientOcclusion& ao = scene_.ambient_occlusion; ao.samples > 0)
        open = ambient_visibility(tracer_, origin, n, ao.distance, SamplePattern(ao.samples), shading_rng(origin, 0x414F),
                                  ts.scratch, ts.rays.shadow);
    const glm::dvec3 local = kAmbient * open * albedo + diffuse + highlights;
    const double t = m.transparency;
    // An opaque surface that mirrors nothing (most), or the depth is spent
    // (shaded as opaque; POV-Ray: black): the bytes the sums below give
    // for t = 0 and reflect = 0, without them.
    if ((t == 0 && m.reflect == 0) || depth >= max_depth_) return local + m.emission;
    const glm::dvec3 view = -glm::normalize(ray.d);
    // Glass (transparency t): the share t meets a smooth dielectric —
    // Fresnel's reflectance f of it mirrored, the rest refracted inside —
    // and keeps the light sources' highlights; the share 1 − t is the
    // opaque surface, itself mirrored by `reflect`.
    double f = 0, cos_t = 0;
    const double cos_i = glm::dot(view, n);
    if (t > 0) f = fresnel_dielectric(cos_i, 1 / m.ior, cos_t);
    const double mirror_weight = (1 - t) * m.reflect + t * (f > 1e-9 ? f : 0);
    glm::dvec3 c = (1 - t) * (1 - m.reflect) * local + t * highlights + m.emission;
    if (mirror_weight > 0) c += mirror_weight * mirror(origin, mirror_direction(-view, n), n, m.roughness, depth, ts);
    if (t > 0 && f < 1) c += t * (1 - f) * inside(p, refract_direction(-view, n, 1 / m.ior, cos_i, cos_t), m, off, depth + 1, ts);
    return c;
}

}  // namespace kerf::render
