#include "render/integrator_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/hemisphere.hpp"
#include "render/lights.hpp"
#include "render/optics.hpp"
#include "render/patterns.hpp"

namespace kerf::render {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// The power heuristic (β = 2): the weight of a sample drawn with density
// `a` when another strategy would have drawn it with density `b`.
double power_weight(double a, double b) { return a * a / (a * a + b * b); }

// A spherical light seen from a point `dist` > radius from its centre: the
// cone it fills and the radiance that gives the point the Whitted tracer's
// irradiance (a light of intensity k lights a facing diffuse surface of
// reflectance ρ to ρ·k): π·k over the cone's solid angle.
struct SphereView {
    double solid_angle, radiance;
};
SphereView sphere_view(const csg::Light& light, const glm::dvec3& l, double dist) {
    const double s = light.radius / dist;
    const double solid_angle = 2 * M_PI * (1 - std::sqrt(std::max(0.0, 1 - s * s)));
    return {solid_angle, M_PI * arriving(light, -l, dist) / solid_angle};
}
}  // namespace

PathTracer::PathTracer(const csg::Scene& scene, const CsgTracer& tracer, int max_depth, std::uint64_t seed,
                       PathLighting lighting)
    : scene_(scene), tracer_(tracer), max_depth_(max_depth), seed_(seed), lighting_(lighting),
      miss_(scene.fog.on() ? scene.fog.color : scene.background) {
    for (csg::Light l : scene.lights) {
        l.direction = glm::normalize(l.direction);
        lights_.push_back(l);
        any_sphere_ |= !l.directional && l.radius > 0 && l.shadows;
    }
}

int PathTracer::light_hit(const glm::dvec3& origin, const glm::dvec3& d, double& tmax) const {
    int best = -1;
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const csg::Light& light = lights_[i];
        // Shadowless lights reach points through solids: seen by next-event
        // estimation only, or a solid would hide what it does not shadow.
        if (light.directional || light.radius <= 0 || !light.shadows) continue;
        const glm::dvec3 oc = light.position - origin;
        const double b = glm::dot(oc, d), c2 = glm::dot(oc, oc) - b * b, r2 = light.radius * light.radius;
        if (glm::dot(oc, oc) <= r2 || c2 >= r2) continue;  // inside it (a point light there), or a miss
        const double t = b - std::sqrt(r2 - c2);
        if (t > 0 && t < tmax) {
            tmax = t;
            best = int(i);
        }
    }
    return best;
}

glm::dvec3 PathTracer::next_event(const glm::dvec3& origin, const glm::dvec3& n, const glm::dvec3& rho,
                                  std::uint64_t& rng, ThreadState& ts) const {
    glm::dvec3 sum(0.0);
    for (const csg::Light& light : lights_) {
        LightView view;
        if (!view_light(light, origin, view)) continue;
        glm::dvec3 l = view.l;
        const double dist = view.dist, k = view.k;
        const bool sphere = !light.directional && light.radius > 0 && dist > light.radius;
        double weight = 1, reach = dist;
        if (sphere) {
            // One direction uniform over the cone (density 1/Ω): the
            // estimate ρ/π · L·cos θ · Ω is ρ·k·cos θ, as in the Whitted tracer.
            if (lighting_ == PathLighting::BsdfOnly && light.shadows) continue;
            const ConeBasis cone(l, dist, light.radius);
            const double u = uniform01(rng), v = uniform01(rng);
            l = cone.direction({u, v}, reach);
            if (lighting_ == PathLighting::Mis && light.shadows) {
                const double ndl = glm::dot(n, l);
                weight = power_weight(1 / (2 * M_PI * (1 - cone.cos_max)), std::max(0.0, ndl) / M_PI);
            }
        }
        const double ndl = glm::dot(n, l);
        if (ndl <= 0) continue;
        if (light.shadows) {
            ++ts.rays.shadow;
            if (tracer_.occluded(TraceRay{origin, l, 0, reach}, ts.scratch)) continue;
        }
        sum += light.color * (k * ndl * weight) * rho;
    }
    return sum;
}

glm::dvec3 PathTracer::radiance(const glm::dvec3& o, const glm::dvec3& d_in, ThreadState& ts,
                                std::uint32_t* surface) const {
    std::uint64_t rng = seed_ * 0x9E3779B97F4A7C15ull ^ 0x70617468u;  // "path"
    mix_bits(rng, o);
    mix_bits(rng, d_in);
    glm::dvec3 L(0.0), beta(1.0);
    glm::dvec3 ro = o, rd = glm::normalize(d_in);
    double tnear = 0;
    // The last scattering: 0 a delta (mirror, glass) or glossy bounce, whose
    // rays count the lights they meet in full; else the density of the
    // diffuse direction, for the MIS weight of a light it meets.
    double bsdf_pdf = 0;
    const csg::Material* medium = nullptr;  // inside a transparent solid of this material
    auto add_fog = [&](double distance) {
        if (!scene_.fog.on()) return;
        const double keep = std::exp(-distance / scene_.fog.distance);
        L += beta * (1 - keep) * scene_.fog.color;
        beta *= keep;
    };
    // The normal at a hit facing the arriving ray (so a CSG exit, a
    // subtrahend's flipped face, is right too).
    auto facing = [&](const TraceHit& hit, const glm::dvec3& p) {
        const glm::dvec3 n = tracer_.normal(hit, p);
        return glm::dot(n, rd) > 0 ? -n : n;
    };
    if (surface) *surface = 0;
    for (int depth = 0;; ++depth) {
        if (medium) {
            // Inside glass (Shader::inside): absorbed on the way to the exit,
            // there reflected back in with Fresnel's probability, else out.
            const csg::Material& m = *medium;
            ++ts.rays.refract;
            tracer_.inside_spans(TraceRay{ro, rd, 0, kInf}, ts.scratch, ts.spans);
            const auto exit = std::find_if(ts.spans.begin(), ts.spans.end(), [&](const Span& sp) { return sp.t1 > tnear; });
            if (exit == ts.spans.end() || exit->t0 > tnear) {  // grazing round-off: not inside after all
                medium = nullptr;
                --depth;
                continue;
            }
            beta *= beer_lambert(m.absorption, exit->t1);
            if (!(exit->t1 < kInf)) {  // never leaves an unbounded solid: a miss through all that glass
                L += beta * miss_;
                break;
            }
            const TraceHit hit{exit->t1, exit->e1};
            const glm::dvec3 q = ro + hit.t * rd;
            if (depth >= max_depth_) break;
            const glm::dvec3 n = facing(hit, q);
            const double off = tracer_.surface_offset(hit, q);
            const double cos_i = -glm::dot(rd, n);
            double cos_t;
            const double f = fresnel_dielectric(cos_i, m.ior, cos_t);
            if (uniform01(rng) < f) {
                rd = mirror_direction(rd, n);
                ro = q;
                tnear = off;
            } else {
                rd = refract_direction(rd, n, m.ior, cos_i, cos_t);
                ro = q - off * n;
                tnear = 0;
                medium = nullptr;
            }
            bsdf_pdf = 0;
            continue;
        }
        TraceHit hit;
        const bool hit_solid = tracer_.intersect(TraceRay{ro, rd, tnear, kInf}, hit, ts.scratch);
        tnear = 0;
        if (depth == 0 && surface && hit_solid) *surface = (hit.surface.leaf + 1) * 2 + hit.surface.cut;
        // A spherical light in front of the solid (the camera does not see
        // lights, as in the Whitted tracer): its radiance as seen from the
        // point the ray left, weighted against next-event estimation there.
        if (depth > 0 && any_sphere_) {
            double t_light = hit_solid ? hit.t : kInf;
            if (const int li = light_hit(ro, rd, t_light); li >= 0) {
                const csg::Light& light = lights_[std::size_t(li)];
                const glm::dvec3 to = light.position - ro;
                const double dist = glm::length(to);
                const SphereView view = sphere_view(light, to / dist, dist);
                double weight = 1;
                if (bsdf_pdf > 0 && lighting_ == PathLighting::LightOnly) weight = 0;
                if (bsdf_pdf > 0 && lighting_ == PathLighting::Mis) weight = power_weight(bsdf_pdf, 1 / view.solid_angle);
                add_fog(t_light);
                L += beta * light.color * (view.radiance * weight);
                break;
            }
        }
        if (!hit_solid) {
            L += beta * miss_;  // the background (or the fog) lights the scene like a sky
            break;
        }
        add_fog(hit.t);
        const glm::dvec3 p = ro + hit.t * rd;
        const glm::dvec3 n = facing(hit, p);
        const csg::Material& m = leaf_material(scene_, hit.surface.mat_leaf);
        L += beta * m.emission;
        if (depth >= max_depth_) break;
        const glm::dvec3 albedo = surface_albedo(scene_, m, hit.surface.mat_leaf, hit.surface.cut, p);
        const double off = tracer_.surface_offset(hit, p);
        const glm::dvec3 origin = p + off * n;
        // One lobe, picked with its share of the surface (shading.cpp's
        // weights): glass t (Fresnel f mirrored, the rest refracted), the
        // opaque rest mirrored by `reflect`, diffuse otherwise.
        const double t = m.transparency, cos_i = -glm::dot(rd, n);
        double f = 0, cos_t = 0;
        if (t > 0) f = fresnel_dielectric(cos_i, 1 / m.ior, cos_t);
        const double p_mirror = (1 - t) * m.reflect + t * f, p_refract = t * (1 - f);
        const double u = uniform01(rng);
        if (u < p_mirror) {
            glm::dvec3 r = mirror_direction(rd, n);
            if (m.roughness > 0) {  // Shader::mirror's cone of half-angle roughness·45°
                const ConeBasis cone(r, 1, std::sin(m.roughness * M_PI / 4));
                double reach;
                const double a = uniform01(rng), b = uniform01(rng);
                r = cone.direction({a, b}, reach);
                if (glm::dot(r, n) <= 0) r = mirror_direction(r, n);
            }
            ++ts.rays.reflect;
            ro = origin;
            rd = r;
            bsdf_pdf = 0;
        } else if (u < p_mirror + p_refract) {
            rd = refract_direction(rd, n, 1 / m.ior, cos_i, cos_t);
            ro = p;
            tnear = off;
            medium = &m;
            bsdf_pdf = 0;
        } else {
            const glm::dvec3 rho = m.diffuse * albedo;
            if (!lights_.empty()) L += beta * next_event(origin, n, rho, rng, ts);
            const double a = uniform01(rng), b = uniform01(rng);
            rd = cosine_direction(n, {a, b});
            ro = origin;
            bsdf_pdf = std::max(glm::dot(rd, n), 1e-12) / M_PI;
            beta *= rho;  // ρ/π · cos θ over the density cos θ / π
            ++ts.rays.reflect;
        }
        if (depth + 1 >= kRouletteFrom) {
            const double q = std::min(0.95, std::max({beta.x, beta.y, beta.z}));
            if (!(q > 0) || uniform01(rng) >= q) break;
            beta /= q;
        }
    }
    return L;
}

}  // namespace kerf::render
