// Ray cones (README.md, "Ray cones"): a pinhole camera's rays all start at
// its position and a point light's shadow rays all end at the light. Around
// such a point (an apex) each thread lists once the units whose balls meet
// a narrow cone of directions, and every later ray of that apex inside the
// cone tests only those, in a loop, nearest the apex first, instead of
// traversing the top BVH. Which units a cone lists never changes an answer
// or the work: a unit left out is one the ray's own ball or chord test
// would drop (its padded ball misses the whole cone), so the rays of any
// cone, on any thread, do the same work.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace kerf::render {

// A point rays start at (`from`: the camera) or end at (a light), built
// once with the tracer (ray_cones.cpp, Impl::build_apexes).
struct Apex {
    glm::dvec3 p{0.0};
    bool from = true;
    double rho = 0;    // a ray's start (from) or end within rho of p (L1) counts as at p
    double reach = 0;  // ... and a shadow ray's start within reach of p (L1): bounds its round-off
    double alpha = 0;  // a cone's half-angle
    double cos_in = 1; // a ray's direction within alpha (less a margin for round-off) of the axis
    // The units nearest p first (`key`: a bound on the distance from p of
    // any point of the unit a ray keeps), and their balls grown by every
    // per-ray slack the ball and chord tests add for a ray of this apex.
    std::vector<std::uint32_t> order;
    std::vector<double> key;
    // Per unit in that order, the direction from p to its centre (unit) and
    // the cosine and sine of its grown ball's angular radius seen from p
    // (-2, 0 when p lies in the ball: every cone meets it).
    std::vector<glm::dvec3> towards;
    std::vector<double> cos_beta, sin_beta;
    double cos_alpha = 1, sin_alpha = 0;
};

struct ConeUnit {
    std::uint32_t item;  // index in the top BVH
    double key;          // Apex::key
};

struct RayCone {
    std::uint64_t owner = 0;      // the tracer it belongs to (CsgTracer::Impl::id)
    std::uint32_t apex = 0;
    glm::dvec3 axis{0.0};         // unit, pointing away from the apex
    std::vector<ConeUnit> units;  // in the apex's order
};

// Per thread (in TraceScratch): the last few cones, reused round-robin.
struct RayCones {
    static constexpr int kSlots = 16, kApexes = 8;
    RayCone cones[kSlots];
    int last[kApexes] = {}, next = 0;  // per apex the cone its last ray used
    std::uint64_t built = 0;  // cones built (tests, tuning)
};

}  // namespace kerf::render
