// Where a pixel's samples go (README.md, "Rendering"): 1 spp through the
// centre; n = k² a jittered k×k grid; other n, n strata per axis with the y
// strata permuted by a golden-ratio step. The jitter generator is seeded by
// (seed, x, y) in full-image coordinates, so neither the thread count nor a
// crop changes a pixel.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include <glm/glm.hpp>

namespace kerf::render {

inline std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

inline double uniform01(std::uint64_t& state) { return double(splitmix64(state) >> 11) * 0x1.0p-53; }

// The layout of n samples in a pixel, worked out once per render.
class SamplePattern {
public:
    explicit SamplePattern(int n) : n_(n), k_(int(std::lround(std::sqrt(double(n))))) {
        step_ = std::max(1, int(std::lround(n * 0.6180339887)));
        while (std::gcd(step_, n) != 1) ++step_;
    }
    int count() const { return n_; }
    // A step coprime with count() near its golden section: i → i·step mod n
    // pairs strata of two patterns without lining them up.
    int step() const { return step_; }

    // The jitter generator of pixel (x, y).
    static std::uint64_t pixel_rng(std::uint64_t seed, int x, int y) {
        std::uint64_t rng = seed * 0x9E3779B97F4A7C15ull ^ (std::uint64_t(y) << 32 | std::uint32_t(x));
        splitmix64(rng);
        return rng;
    }

    // The generator of `rng` as it is after `samples` calls of offset():
    // splitmix64 is a counter, and offset() draws two numbers.
    static void skip(std::uint64_t& rng, int samples) { rng += 2 * std::uint64_t(samples) * 0x9E3779B97F4A7C15ull; }

    // Sample i inside the unit pixel.
    glm::dvec2 offset(int i, std::uint64_t& rng) const {
        const double jx = uniform01(rng), jy = uniform01(rng);
        if (k_ * k_ == n_) return {(i % k_ + jx) / k_, (i / k_ + jy) / k_};
        return {(i + jx) / n_, (int((std::int64_t(i) * step_) % n_) + jy) / n_};
    }

private:
    int n_, k_, step_;
};

}  // namespace kerf::render
