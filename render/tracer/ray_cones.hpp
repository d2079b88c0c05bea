// Ray cones (README.md, "Ray cones"): a pinhole camera's rays all start at
// its position and a point light's shadow rays all end at the light. Around
// such a point (an apex) each thread lists once the units whose balls meet
// a narrow cone of directions, and every later ray of that apex inside the
// cone tests only those, in a loop, nearest the apex first, instead of
// traversing the top BVH. Which units a cone lists never changes an answer
// or the work: a unit left out is one the ray's own ball or chord test
// would drop (its padded ball misses the whole cone), so the rays of any
// cone, on any thread, do the same work.
//
// Two levels for big crowds (257 to kMaxTwoLevelUnits units of about one
// ball size): a scan of every unit per cone is then most of the cost, and a
// cone narrow enough for a short list needs many. So wide cones (level 0)
// are listed from all units, and the narrow cones (level 1) the rays use
// from the wide one holding them (~80 scanned, ~20 listed at cells_1000),
// each sorted by its own key (where its rays can first reach a unit), and
// a ray's cone is its direction's cell in a grid: its work depends on the
// ray alone, as with one level.
//
// Crowds whose ball sizes spread over orders of magnitude (257 to
// kMaxSpreadUnits units: the spiral family) get two levels too, their angle
// from the balls most rays meet (ray_cones.cpp, spread_radius), and a cone
// that would list too many units is full: its rays take the BVH.
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
    // Per level (0 wide, up to `levels` - 1 the rays' own): a cone's
    // half-angle; cos_in: a ray's direction within alpha (less a margin for
    // round-off) of the axis; cos_sub: a level's axis within alpha minus the
    // next level's alpha (less the margin) of the axis, so that the narrower
    // cone lies in it.
    static constexpr int kLevels = 2;
    int levels = 1;
    double alpha[kLevels] = {}, cos_in[kLevels] = {}, cos_sub[kLevels] = {};
    double cos_alpha[kLevels] = {}, sin_alpha[kLevels] = {};
    double cos_key[kLevels] = {}, sin_key[kLevels] = {};  // of alpha + 1e-6 (cone_key)
    // A frame around the crowd's direction and per level the spacing of a
    // grid in its gnomonic plane that new cones' axes snap to (0: none).
    glm::dvec3 e0{0, 0, 1}, e1{1, 0, 0}, e2{0, 1, 0};
    double grid[kLevels] = {};
    // Per level, the most units a cone lists; one that would list more is
    // full (RayCone::full). Limited only for crowds of spread sizes.
    std::size_t max_units[kLevels] = {~std::size_t(0), ~std::size_t(0)};
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
    std::vector<double> dist;  // |centre - p|
    // A camera (from): per unit in that order, what the outer chord's test
    // (ball_chords.hpp, outer_chord_reaches) and the ball test
    // (ball_misses_from) find from the ray's origin alone, for rays that
    // start exactly at p: the same numbers, once.
    struct AtP {
        glm::dvec3 w;  // centre - p
        double w1;     // |w|₁
        double rr2;    // the grown radius, squared
        double round;  // 1e-13·(w1² + rr²)
    };
    std::vector<AtP> at_p;
    // The units' terms for a ray from o: at_p's when o is exactly p, else
    // none (the ray finds its own).
    const AtP* terms_at(const glm::dvec3& o) const { return !at_p.empty() && o == p ? at_p.data() : nullptr; }
};

struct ConeUnit {
    std::uint32_t item;  // index in the top BVH
    std::uint32_t j;     // index in the apex's order
    double key;          // Apex::key, or a narrow cone's own (ray_cones.cpp, cone_key)
};

struct RayCone {
    std::uint64_t owner = 0;      // the tracer it belongs to (CsgTracer::Impl::id)
    std::uint32_t apex = 0;
    int level = 0;
    std::int64_t u = 0, v = 0;    // two levels: its cell (ray_cones.cpp, find_cell_cone)
    glm::dvec3 axis{0.0};         // unit, pointing away from the apex
    std::vector<ConeUnit> units;  // in the apex's order
    bool full = false;            // listed no units: more than Apex::max_units (its rays take the BVH)
};

// Per thread (in TraceScratch): the last few cones of each level, reused
// round-robin (one level: the first kScan slots, scanned), or the grid
// cells' cones (two levels), each in the slot of its cell's low bits and
// its apex's parity (ray_cones.cpp, cell_slot): a 16×16 patch of cells
// per apex stays, and a ray finds its cell's cone without a scan.
struct RayCones {
    static constexpr int kSlots = 512, kScan = 16, kApexes = 8;
    static_assert(kSlots < 65535, "last_cell holds a slot + 1 in 16 bits");
    RayCone cones[Apex::kLevels][kSlots];
    int last[Apex::kLevels][kApexes] = {}, next[Apex::kLevels] = {};  // per apex the cone its last ray used
    // Two levels: per apex, the rays' level's cone its last ray used, as
    // its slot + 1 (0: none; an index, not a pointer, so a copied RayCones
    // cannot point into its source) (ray_cones.cpp, find_cell_cone).
    std::uint16_t last_cell[kApexes] = {};
    std::uint64_t built = 0;  // cones built (tests, tuning)
    std::vector<ConeUnit> listing;  // a cone's units while it is listed (ray_cones.cpp, build_cone)
};

}  // namespace kerf::render
