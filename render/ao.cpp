#include "render/ao.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kerf::render {

double ambient_visibility(const CsgTracer& tracer, const glm::dvec3& origin, const glm::dvec3& n, double distance,
                          const SamplePattern& pattern, std::uint64_t rng, TraceScratch& scratch, std::uint64_t& rays) {
    // An orthonormal frame about n (Duff et al.'s branchless construction).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1 / (sign + n.z), b = n.x * n.y * a;
    const glm::dvec3 t{1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    const glm::dvec3 s{b, sign + n.y * n.y * a, -n.y};
    int open = 0;
    for (int i = 0; i < pattern.count(); ++i) {
        const glm::dvec2 u = pattern.offset(i, rng);
        // Malley: radius √u uniform over the disk, lifted by √(1 − r²): cosine-weighted.
        const double r = std::sqrt(u.x), phi = 2 * std::numbers::pi * u.y;
        const glm::dvec3 d = r * std::cos(phi) * t + r * std::sin(phi) * s + std::sqrt(std::max(0.0, 1 - u.x)) * n;
        ++rays;
        if (!tracer.occluded(TraceRay{origin, d, 0, distance}, scratch)) ++open;
    }
    return double(open) / pattern.count();
}

}  // namespace kerf::render
