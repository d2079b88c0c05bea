#include "render/shading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/lights.hpp"

namespace kerf::render {

namespace {
constexpr double kAmbient = 0.1;  // POV-Ray's default ambient: shadows are not pitch black

// x^s for the Blinn–Phong highlight: whole exponents (the usual 8..256) by
// repeated squaring, a few multiplies instead of libm's pow (~2 % of a
// simple render); others by pow.
double highlight(double x, double s) {
    if (s >= 0 && s <= 1024 && s == std::floor(s)) {
        double r = 1, base = x;
        for (unsigned e = unsigned(s); e != 0; e >>= 1) {
            if (e & 1) r *= base;
            base *= base;
        }
        return r;
    }
    return std::pow(x, s);
}
}  // namespace

Shader::Shader(const csg::Scene& scene, const CsgTracer& tracer, int max_reflect_depth)
    : scene_(scene), tracer_(tracer), max_depth_(max_reflect_depth) {
    for (csg::Light l : scene.lights) {
        l.direction = glm::normalize(l.direction);  // once, not per shading point
        lights_.push_back(l);
        patterns_.emplace_back(int(l.samples));
    }
}

glm::dvec3 Shader::radiance(const TraceRay& ray, int depth, ThreadState& ts, std::uint32_t* surface) const {
    TraceHit hit;
    if (!tracer_.intersect(ray, hit, ts.scratch)) {
        if (surface) *surface = 0;
        return scene_.background;
    }
    if (surface) *surface = (hit.surface.leaf + 1) * 2 + hit.surface.cut;
    const glm::dvec3 p = ray.o + hit.t * ray.d;
    glm::dvec3 n = tracer_.normal(hit, p);
    if (glm::dot(n, ray.d) > 0) n = -n;  // grazing round-off: light the side we see
    static const csg::Material fallback;  // a scene without materials: light grey
    const csg::Leaf& leaf = scene_.leaves[hit.surface.mat_leaf];
    const csg::Material& m = leaf.material < scene_.materials.size() ? scene_.materials[leaf.material] : fallback;
    const glm::dvec3 albedo = hit.surface.cut ? m.interior : m.color;
    const glm::dvec3 origin = p + tracer_.surface_offset(hit, p) * n;
    const glm::dvec3 view = -glm::normalize(ray.d);

    glm::dvec3 c = kAmbient * albedo;
    // The surface's response to light arriving from unit direction l.
    auto respond = [&](const glm::dvec3& l, double ndl) {
        const glm::dvec3 h = glm::normalize(l + view);
        return m.diffuse * ndl * albedo + m.specular * highlight(std::max(0.0, glm::dot(n, h)), m.shininess);
    };
    for (std::size_t li = 0; li < lights_.size(); ++li) {
        const csg::Light& light = lights_[li];
        glm::dvec3 l;
        double dist, k;
        if (light.directional) {
            l = -light.direction;
            dist = std::numeric_limits<double>::infinity();
            k = light.intensity;
        } else {
            l = light.position - origin;
            dist = glm::length(l);
            if (dist == 0) continue;
            l /= dist;
            k = arriving(light, -l, dist);
        }
        if (k <= 0) continue;
        if (light.radius <= 0 || dist <= light.radius) {
            const double ndl = glm::dot(n, l);
            if (ndl <= 0) continue;
            if (light.shadows) {
                ++ts.rays.shadow;
                if (tracer_.occluded(TraceRay{origin, l, 0, dist}, ts.scratch)) continue;
            }
            c += light.color * k * respond(l, ndl);
            continue;
        }
        // A sphere: the mean response over stratified directions into the
        // cone it fills, each with its own shadow ray (soft shadows).
        const ConeBasis cone(l, dist, light.radius);
        const SamplePattern& pattern = patterns_[li];
        std::uint64_t rng = shading_rng(origin, li);
        glm::dvec3 sum(0);
        for (int i = 0; i < pattern.count(); ++i) {
            double reach;
            const glm::dvec3 dir = cone.direction(pattern.offset(i, rng), reach);
            const double ndl = glm::dot(n, dir);
            if (ndl <= 0) continue;
            if (light.shadows) {
                ++ts.rays.shadow;
                if (tracer_.occluded(TraceRay{origin, dir, 0, reach}, ts.scratch)) continue;
            }
            sum += respond(dir, ndl);
        }
        c += light.color * k * sum / double(pattern.count());
    }
    if (m.reflect > 0 && depth < max_depth_) {
        ++ts.rays.reflect;
        const glm::dvec3 r = ray.d - 2 * glm::dot(ray.d, n) * n;
        const glm::dvec3 rc = radiance(TraceRay{origin, r, 0, std::numeric_limits<double>::infinity()}, depth + 1, ts);
        c = (1 - m.reflect) * c + m.reflect * rc;
    }
    return c;
}

}  // namespace kerf::render
