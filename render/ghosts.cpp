#include "render/ghosts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::render {

namespace {

struct GhostSurface {
    double t;
    glm::dvec3 color;  // shaded, linear
    double alpha;
    std::uint32_t id;
};

}  // namespace

GhostLayers::GhostLayers(const csg::Scene& scene, const CsgTracer& solid, bool use_float)
    : solid_(solid), fog_(scene.fog) {
    for (const csg::Scene& ghost : scene.ghosts) {
        if (ghost.root == csg::kNone) continue;
        layers_.push_back({&ghost, std::make_unique<CsgTracer>(ghost, use_float)});
        bounds_.extend(ghost.bounds());
    }
}

GhostLayers::~GhostLayers() = default;

glm::dvec3 GhostLayers::over(const TraceRay& ray, const glm::dvec3& behind, ThreadState& ts, double* opacity,
                             std::uint32_t* surface) const {
    if (opacity) *opacity = 0;
    // One list per thread, grown once: no allocation per ray.
    static thread_local std::vector<GhostSurface> found;
    found.clear();
    const double dlen = glm::length(ray.d);
    const glm::dvec3 view = ray.d / dlen;
    for (std::size_t k = 0; k < layers_.size(); ++k) {
        const Layer& layer = layers_[k];
        layer.tracer->inside_spans(ray, ts.scratch, ts.spans);
        auto add = [&](double t, const SpanEnd& end) {
            const csg::Leaf& leaf = layer.scene->leaves[end.mat_leaf];
            const csg::Material& m = layer.scene->materials[leaf.material];
            const glm::dvec3 n = layer.tracer->normal(TraceHit{t, end}, ray.o + t * ray.d);
            // A light at the eye: faces turned away from the view darken.
            const double shade = 0.35 + 0.65 * std::abs(glm::dot(n, view));
            const std::uint32_t id = (std::uint32_t(k) + 1) * 0x9E3779B9u ^ (end.leaf * 0x85EBCA6Bu + end.part);
            glm::dvec3 c = m.color * shade;
            if (fog_.on()) {
                const double keep = std::exp(-t * dlen / fog_.distance);
                c = keep * c + (1 - keep) * fog_.color;
            }
            found.push_back({t, c, std::clamp(1 - m.transparency, 0.0, 1.0), id});
        };
        for (const Span& s : ts.spans) {
            if (s.t0 > ray.tnear) add(s.t0, s.e0);  // not where the ray starts inside the ghost
            if (s.t1 < ray.tfar) add(s.t1, s.e1);
        }
    }
    if (found.empty()) return behind;
    // Only what lies in front of the solid, or on it within the tracer's
    // surface tolerance (a `#` part's faces are the solid's own).
    TraceHit hit;
    double limit = std::numeric_limits<double>::infinity();
    if (solid_.intersect(ray, hit, ts.scratch)) limit = hit.t + solid_.surface_offset(hit, ray.o + hit.t * ray.d) / dlen;
    std::sort(found.begin(), found.end(), [](const GhostSurface& a, const GhostSurface& b) { return a.t < b.t; });
    glm::dvec3 color(0.0);
    double through = 1;  // the share of what lies behind that still shows
    bool first = true;
    for (const GhostSurface& g : found) {
        if (g.t > limit) break;
        if (first && surface) *surface = *surface * 31u + g.id;
        first = false;
        color += through * g.alpha * g.color;
        through *= 1 - g.alpha;
    }
    if (opacity) *opacity = 1 - through;
    return color + through * behind;
}

}  // namespace kerf::render
