#include "render/aov.hpp"

#include <limits>

namespace kerf::render {

int aov_channels(Aov aov) { return aov == Aov::Depth || aov == Aov::Hits ? 1 : 3; }

ImageContent aov_content(Aov aov) {
    switch (aov) {
        case Aov::Depth: return ImageContent::Depth;
        case Aov::Normal: return ImageContent::Normal;
        case Aov::Hits: return ImageContent::Hits;
        case Aov::None: break;
    }
    return ImageContent::Color;
}

void aov_pixel(Aov aov, const CameraModel& camera, const CsgTracer& tracer, int x, int y, ThreadState& ts,
               bool traced, float* out) {
    ++ts.rays.primary;
    const std::uint64_t spans_before = ts.scratch.counters.spans_found;
    glm::dvec3 o, d;
    TraceHit hit;
    bool found = false;
    if (traced && camera.ray(x + 0.5, y + 0.5, o, d)) {
        found = tracer.intersect(TraceRay{o, d, 0, std::numeric_limits<double>::infinity()}, hit, ts.scratch);
    }
    if (aov == Aov::Depth) {
        out[0] = found ? float(hit.t) : std::numeric_limits<float>::infinity();
    } else if (aov == Aov::Normal) {
        const glm::dvec3 n = found ? tracer.normal(hit, o + hit.t * d) : glm::dvec3(0.0);
        out[0] = float(n.x), out[1] = float(n.y), out[2] = float(n.z);
    } else {
        out[0] = float(ts.scratch.counters.spans_found - spans_before);
    }
}

}  // namespace kerf::render
