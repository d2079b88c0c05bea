#include "render/ao.hpp"

#include "render/hemisphere.hpp"

namespace kerf::render {

double ambient_visibility(const CsgTracer& tracer, const glm::dvec3& origin, const glm::dvec3& n, double distance,
                          const SamplePattern& pattern, std::uint64_t rng, TraceScratch& scratch, std::uint64_t& rays) {
    int open = 0;
    for (int i = 0; i < pattern.count(); ++i) {
        const glm::dvec3 d = cosine_direction(n, pattern.offset(i, rng));
        ++rays;
        if (!tracer.occluded(TraceRay{origin, d, 0, distance}, scratch)) ++open;
    }
    return double(open) / pattern.count();
}

}  // namespace kerf::render
