// Adaptive anti-aliasing (docs/quality.md): a first pass traces one ray
// through every pixel centre, stores its colour in the image and keeps what
// it looks like (display codes, surface hit) for the whole region + a ring.
// A pixel is a candidate if any of its 8 neighbours hit another surface (a
// silhouette, an edge between leaves, a cut) or differs from it by more
// than the threshold in a display (sRGB) channel (shadow edges,
// highlights). A candidate gets probe samples at its 4 corners; if they all
// look like its centre it is their mean with the centre; if they fall into
// two runs round the pixel, one straight edge crosses it, located on its
// sides (edge_coverage.hpp); else it gets the uniform pattern of
// RenderOptions::aa_samples (the pixel `--spp 16` gives), unless its
// shading changes linearly on one surface (9 samples; adaptive_aa.cpp). A
// side sample between two surfaces asks only which one it hits. The decision
// reads only first-pass values of full-image coordinates and samples
// without jitter, so the thread count and a crop never change a pixel: the
// first pass covers the region plus a one-pixel ring.
#pragma once
#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "csg/srgb.hpp"

#include "render/image/big_buffer.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

class CentreSamples {
public:
    // `region` grown by one pixel, clamped to the image.
    CentreSamples(const std::array<int, 4>& region, int width, int height)
        : x0_(std::max(0, region[0] - 1)), y0_(std::max(0, region[1] - 1)),
          x1_(std::min(width, region[2] + 1)), y1_(std::min(height, region[3] + 1)),
          srgb_(srgb_table()) {
        looks_.resize(std::size_t(x1_ - x0_) * std::size_t(y1_ - y0_));  // uninitialised: set() fills all
    }
    std::array<int, 4> area() const { return {x0_, y0_, x1_, y1_}; }

    // `surface`: 0 for a miss, else an id of the surface hit (Shader::radiance).
    // `stand_in`: c is not the sample's colour but what it is compared as
    // (the ground as the background).
    void set(int x, int y, const glm::dvec3& c, std::uint32_t surface, bool stand_in = false) {
        looks_[index(x, y)] = look(c, surface) | std::uint64_t(stand_in) << 24;
    }

    // The centre sample's colour to 8-bit precision (linear, decoded from
    // its display codes), when the look holds it: not a stand-in, and no
    // channel at 255 (which may have been clipped).
    std::optional<glm::dvec3> color(int x, int y) const {
        const std::uint64_t l = looks_[index(x, y)];
        if (l >> 24 & 1) return std::nullopt;
        glm::dvec3 c;
        for (int k = 0; k < 3; ++k) {
            const int code = int(l >> (8 * k) & 0xFF);
            if (code == 255) return std::nullopt;
            c[k] = decoded()[code];
        }
        return c;
    }

    // Whether pixel (x, y) of the region needs more samples. `threshold`:
    // in 8-bit display codes.
    bool needs_more(int x, int y, int threshold) const {
        const std::uint64_t* c = &looks_[index(x, y)];
        const std::uint64_t l = *c;
        if (x > x0_ && x + 1 < x1_ && y > y0_ && y + 1 < y1_) {
            // Inside: all eight neighbours look the same (most pixels).
            const std::size_t w = std::size_t(x1_ - x0_);
            const std::uint64_t *up = c - w - 1, *down = c + w - 1;
            if (((up[0] ^ l) | (up[1] ^ l) | (up[2] ^ l) | (c[-1] ^ l) | (c[1] ^ l) | (down[0] ^ l) | (down[1] ^ l) |
                 (down[2] ^ l)) == 0)
                return false;
            // A gradient: each neighbour within the threshold.
            for (const std::uint64_t d : {up[0], up[1], up[2], c[-1], c[1], down[0], down[1], down[2]})
                if (d != l && !alike(d, l, threshold)) return true;
            return false;
        }
        for (int ny = std::max(y0_, y - 1); ny <= std::min(y1_ - 1, y + 1); ++ny)
            for (int nx = std::max(x0_, x - 1); nx <= std::min(x1_ - 1, x + 1); ++nx) {
                const std::uint64_t d = looks_[index(nx, ny)];
                if (d == l) continue;
                if (!alike(d, l, threshold)) return true;
            }
        return false;
    }

    // The surface pixel (x, y)'s centre sample hit (0: none).
    std::uint32_t surface(int x, int y) const { return std::uint32_t(looks_[index(x, y)] >> 32); }

    // Whether a sample (colour c, surface) looks like pixel (x, y)'s centre.
    bool looks_alike(int x, int y, const glm::dvec3& c, std::uint32_t surface, int threshold) const {
        return alike(look(c, surface), looks_[index(x, y)], threshold);
    }

    // Whether two samples look alike.
    bool alike(const glm::dvec3& a, std::uint32_t a_surface, const glm::dvec3& b, std::uint32_t b_surface,
               int threshold) const {
        return alike(look(a, a_surface), look(b, b_surface), threshold);
    }

private:
    // What a sample looks like: surface << 32 | its 8-bit display codes.
    std::uint64_t look(const glm::dvec3& c, std::uint32_t surface) const {
        return std::uint64_t(surface) << 32 | std::uint32_t(srgb_byte(srgb_, float(c.x))) |
               std::uint32_t(srgb_byte(srgb_, float(c.y))) << 8 | std::uint32_t(srgb_byte(srgb_, float(c.z))) << 16;
    }
    static bool alike(std::uint64_t a, std::uint64_t b, int threshold) {
        if (a >> 32 != b >> 32) return false;  // another surface
        for (int k = 0; k < 24; k += 8)
            if (std::abs(int((a >> k) & 0xFF) - int((b >> k) & 0xFF)) > threshold) return false;
        return true;
    }
    static const std::array<double, 256>& decoded() {
        static const std::array<double, 256> table = [] {
            std::array<double, 256> t{};
            for (int k = 0; k < 256; ++k) t[k] = csg::srgb_to_linear(k / 255.0);
            return t;
        }();
        return table;
    }
    std::size_t index(int x, int y) const { return std::size_t(y - y0_) * std::size_t(x1_ - x0_) + std::size_t(x - x0_); }
    int x0_, y0_, x1_, y1_;
    const SrgbTable& srgb_;
    BigVector<std::uint64_t> looks_;
};

}  // namespace kerf::render
