#include "render/patterns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace kerf::render {

namespace {

constexpr double kBoundaryNudge = 1e-6;

// ⌊x⌋ mod 2 as 0 or 1, exact for any finite double (fmod of an integer-valued double is exact).
double parity(double x) { return std::abs(std::fmod(std::floor(x + kBoundaryNudge), 2.0)); }

// A lattice coordinate wrapped to 32 bits: the noise repeats every 2³² units,
// far beyond where double coordinates still resolve a unit cell's interior.
std::uint32_t lattice(double x) { return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::fmod(x, 4294967296.0))); }

// A value in [0, 1] for a lattice point: an integer hash (murmur-style finaliser).
double corner(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    std::uint64_t h = x * 0x9E3779B97F4A7C15ull ^ (y + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full ^
                      (z + 0x165667B19E3779F9ull) * 0xD6E8FEB86659FD93ull;
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ull;
    h ^= h >> 33;
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// Four octaves, weights 8:4:2:1 over their sum, each a rotated-lattice-free
// doubling of frequency: a convex mix of values in [0, 1].
double fractal_noise(const glm::dvec3& q) {
    double sum = 0, weight = 8, total = 0, f = 1;
    for (int i = 0; i < 4; ++i, weight /= 2, f *= 2) {
        sum += weight * lattice_noise(q * f + glm::dvec3(0.37 * i, 0.71 * i, 0.13 * i));
        total += weight;
    }
    return sum / total;
}

}  // namespace

double lattice_noise(const glm::dvec3& q) {
    const glm::dvec3 fl = glm::floor(q);
    const glm::dvec3 t = q - fl;
    const std::uint32_t x = lattice(fl.x), y = lattice(fl.y), z = lattice(fl.z);
    const double u = fade(t.x), v = fade(t.y), w = fade(t.z);
    auto lerp = [](double a, double b, double s) { return a + s * (b - a); };
    const double x00 = lerp(corner(x, y, z), corner(x + 1, y, z), u);
    const double x10 = lerp(corner(x, y + 1, z), corner(x + 1, y + 1, z), u);
    const double x01 = lerp(corner(x, y, z + 1), corner(x + 1, y, z + 1), u);
    const double x11 = lerp(corner(x, y + 1, z + 1), corner(x + 1, y + 1, z + 1), u);
    const double r = lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
    return std::clamp(r, 0.0, 1.0);  // lerp round-off must not step outside
}

double pattern_value(csg::Pattern pattern, const glm::dvec3& q) {
    switch (pattern) {
        case csg::Pattern::None:
        case csg::Pattern::Image: return 0;  // a colour, not a value: texture.hpp
        case csg::Pattern::Checker: return std::abs(std::fmod(std::floor(q.x + kBoundaryNudge) + std::floor(q.y + kBoundaryNudge) +
                                                                  std::floor(q.z + kBoundaryNudge),
                                                              2.0));
        case csg::Pattern::Stripes: return parity(q.x);
        case csg::Pattern::Gradient: return q.x - std::floor(q.x);
        case csg::Pattern::Noise: return fractal_noise(q);
        case csg::Pattern::Marble: return 0.5 + 0.5 * std::sin(std::numbers::pi * (q.x + 4 * fractal_noise(q)));
        case csg::Pattern::Wood: {
            const double r = std::sqrt(q.x * q.x + q.y * q.y) + 0.5 * fractal_noise(q);
            return r - std::floor(r);
        }
    }
    return 0;
}

}  // namespace kerf::render
