// Point membership by the tracer, for the lower tests that judge a lowered
// solid against a closed form: the spans of a ray along `d` through `p`
// (from 40 units before it to 40 after) hold p.
#pragma once
#include <vector>

#include "render/tracer/tracer.hpp"

namespace kerf::test {

inline bool traced_inside(const render::CsgTracer& tr, render::TraceScratch& scratch, const glm::dvec3& p,
                          const glm::dvec3& d) {
    render::TraceRay ray{p - 40.0 * d, d, 0, 80};
    std::vector<render::Span> spans;
    tr.inside_spans(ray, scratch, spans);
    for (const auto& s : spans)
        if (s.t0 < 40 && 40 < s.t1) return true;
    return false;
}

}  // namespace kerf::test
