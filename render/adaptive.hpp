// Adaptive anti-aliasing (docs/quality.md): a first pass traces one ray
// through every pixel centre, stores its colour in the image and keeps what
// it looks like (display codes, surface hit) for a band of the region + a
// ring (adaptive_aa.hpp).
// A pixel is a candidate if any of its 8 neighbours hit another surface (a
// silhouette, an edge between leaves, a cut) or differs from it by more
// than the threshold in a display (sRGB) channel (shadow edges,
// highlights). A candidate first probes the corners next to its unlike
// neighbours; if they all look like its centre it keeps the centre (if
// that was all 4 corners, it is their mean with the centre); else it
// probes all 4; if they fall into
// two runs round the pixel (by look, or by surface where three looks are
// two surfaces, one of them shaded linearly), one straight edge crosses
// it, located on its sides (edge_coverage.hpp); else it gets the uniform pattern of
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

#include <emmintrin.h>

#include <glm/glm.hpp>

#include "csg/srgb.hpp"

#include "render/image/big_buffer.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

// The corners of a pixel next to the neighbours in `neighbours` (bits as
// CentreSamples::unlike_neighbours gives them): bit 0 the corner (x, y),
// 1 (x + 1, y), 2 (x, y + 1), 3 (x + 1, y + 1). A straight edge between
// the pixel's centre and a neighbour's that crosses the pixel puts one of
// the corners next to that neighbour on the neighbour's side.
inline unsigned corners_next_to(unsigned neighbours) {
    static constexpr unsigned kNext[8] = {1, 3, 2, 5, 10, 4, 12, 8};
    unsigned corners = 0;
    for (int k = 0; k < 8; ++k)
        if (neighbours >> k & 1) corners |= kNext[k];
    return corners;
}

class CentreSamples {
public:
    // `region` grown by one pixel, clamped to the image; `rows` of it held
    // at a time (a band of the region and the row either side).
    CentreSamples(const std::array<int, 4>& region, int width, int height, int rows)
        : x0_(std::max(0, region[0] - 1)), y0_(std::max(0, region[1] - 1)),
          x1_(std::min(width, region[2] + 1)), y1_(std::min(height, region[3] + 1)),
          first_row_(y0_), srgb_(srgb_table()) {
        looks_.resize(std::size_t(x1_ - x0_) * std::size_t(std::min(rows, y1_ - y0_)));  // uninitialised: set() fills all
    }
    std::array<int, 4> area() const { return {x0_, y0_, x1_, y1_}; }

    // Holds the rows from `y` on (at most `rows` of them) from now: those
    // already set from y up to `set_to` move along, the rest are set next.
    void hold_from(int y, int set_to) {
        const std::size_t w = std::size_t(x1_ - x0_);
        std::copy(looks_.begin() + std::ptrdiff_t(std::size_t(y - first_row_) * w),
                  looks_.begin() + std::ptrdiff_t(std::size_t(set_to - first_row_) * w), looks_.begin());
        first_row_ = y;
    }

    // `surface`: 0 for a miss, else an id of the surface hit (Shader::radiance).
    // `stand_in`: c is not the sample's colour but what it is compared as
    // (the ground as the background).
    // Returns the look, c's display codes in its low 24 bits.
    std::uint64_t set(int x, int y, const glm::dvec3& c, std::uint32_t surface, bool stand_in = false) {
        return set_look(x, y, look(c, surface), stand_in);
    }
    // set() with c's look known (look()).
    std::uint64_t set_look(int x, int y, std::uint64_t l, bool stand_in) {
        looks_[index(x, y)] = l | std::uint64_t(stand_in) << 24;
        return l;
    }

    // The looks of row y from pixel x on, to be set in place (set_look()
    // with stand_in false is `row(x, y)[i] = l` for pixel x + i).
    std::uint64_t* row(int x, int y) { return &looks_[index(x, y)]; }

    // set_look(x, y, l, false) for pixels [x0, x1) of row y (a culled
    // block's row, all misses).
    void set_looks(int x0, int x1, int y, std::uint64_t l) {
        std::fill_n(looks_.begin() + std::ptrdiff_t(index(x0, y)), std::max(0, x1 - x0), l);
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

    // Which of pixel (x, y)'s 8 neighbours do not look like it (0: it
    // keeps its centre): bit k for the k-th in reading order, (-1, -1),
    // (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1).
    // `threshold`: in 8-bit display codes.
    [[gnu::always_inline]] unsigned unlike_neighbours(int x, int y, int threshold) const {
        if (x == x0_ || x + 1 == x1_ || y == y0_ || y + 1 == y1_) return unlike_at_border(x, y, threshold);
        // Inside: alike() of all eight neighbours at once, two to a
        // register: per byte, how far each lies past what alike() allows
        // (the codes: the threshold; the stand-in flag: any; the surface:
        // nothing), all zero for a pixel that keeps its centre. Most
        // pixels, so no branch per neighbour.
        const std::uint64_t* c = &looks_[index(x, y)];
        const std::size_t w = std::size_t(x1_ - x0_);
        const std::uint64_t *up = c - w - 1, *down = c + w - 1;
        const std::uint64_t t = std::uint64_t(threshold);
        const __m128i allowed = _mm_set1_epi64x(std::int64_t(t | t << 8 | t << 16 | 0xFFull << 24));
        const __m128i centre = _mm_set1_epi64x(std::int64_t(*c));
        const auto past = [&](__m128i v) {
            const __m128i apart = _mm_or_si128(_mm_subs_epu8(v, centre), _mm_subs_epu8(centre, v));
            return _mm_subs_epu8(apart, allowed);
        };
        const __m128i pairs[4] = {past(_mm_loadu_si128(reinterpret_cast<const __m128i*>(up))),
                                  past(_mm_set_epi64x(std::int64_t(c[-1]), std::int64_t(up[2]))),
                                  past(_mm_set_epi64x(std::int64_t(down[0]), std::int64_t(c[1]))),
                                  past(_mm_loadu_si128(reinterpret_cast<const __m128i*>(down + 1)))};
        const __m128i zero = _mm_setzero_si128();
        const __m128i any = _mm_or_si128(_mm_or_si128(pairs[0], pairs[1]), _mm_or_si128(pairs[2], pairs[3]));
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(any, zero)) == 0xFFFF) return 0;
        unsigned unlike = 0;
        for (int k = 0; k < 4; ++k) {
            const unsigned same = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(pairs[k], zero)));
            unlike |= unsigned((same & 0xFF) != 0xFF) << (2 * k) | unsigned(same >> 8 != 0xFF) << (2 * k + 1);
        }
        return unlike;
    }

    // The end (exclusive) of the run of pixels from x on row y, inside the
    // area's border and before `limit`, whose 3 × 3 neighbourhoods all hold
    // exactly pixel (x, y)'s look, so that unlike_neighbours() is 0 for
    // them; x when there is none. Background and flat faces are such runs:
    // one scan of 3 looks a column instead of the 8-neighbour test a pixel.
    int uniform_run(int x, int y, int limit) const {
        if (x == x0_ || y == y0_ || y + 1 == y1_) return x;
        const std::uint64_t* c = &looks_[index(x, y)];
        const std::size_t w = std::size_t(x1_ - x0_);
        const std::uint64_t *up = c - w, *down = c + w;
        const std::uint64_t l = *c;
        // Columns x - 1 up to x + k - 1 (at most the area's last, and
        // `limit`) hold the look on all three rows.
        const int last = std::min(x1_, limit + 1) - x;
        int k = -1;
        while (k < last && c[k] == l && up[k] == l && down[k] == l) ++k;
        return std::max(x, x + k - 1);
    }

    // The surface pixel (x, y)'s centre sample hit (0: none).
    std::uint32_t surface(int x, int y) const { return std::uint32_t(looks_[index(x, y)] >> 32); }

    // Whether a sample (colour c, surface) looks like pixel (x, y)'s centre.
    bool looks_alike(int x, int y, const glm::dvec3& c, std::uint32_t surface, int threshold) const {
        return looks_alike(x, y, look(c, surface), threshold);
    }
    // The same for a sample's look (look()).
    bool looks_alike(int x, int y, std::uint64_t l, int threshold) const {
        return alike(l, looks_[index(x, y)], threshold);
    }

    // Whether two samples look alike.
    bool alike(const glm::dvec3& a, std::uint32_t a_surface, const glm::dvec3& b, std::uint32_t b_surface,
               int threshold) const {
        return alike(look(a, a_surface), look(b, b_surface), threshold);
    }

    // What a sample looks like: surface << 32 | its 8-bit display codes.
    std::uint64_t look(const glm::dvec3& c, std::uint32_t surface) const {
        return std::uint64_t(surface) << 32 | std::uint32_t(srgb_byte(srgb_, float(c.x))) |
               std::uint32_t(srgb_byte(srgb_, float(c.y))) << 8 | std::uint32_t(srgb_byte(srgb_, float(c.z))) << 16;
    }

    // Whether two looks (look()) are alike: the same surface, and each
    // display code within the threshold.
    static bool alike(std::uint64_t a, std::uint64_t b, int threshold) {
        if (a >> 32 != b >> 32) return false;  // another surface
        for (int k = 0; k < 24; k += 8)
            if (std::abs(int((a >> k) & 0xFF) - int((b >> k) & 0xFF)) > threshold) return false;
        return true;
    }

private:
    // unlike_neighbours() of a pixel on the border of the area, neighbour by neighbour.
    [[gnu::noinline]] unsigned unlike_at_border(int x, int y, int threshold) const {
        const std::uint64_t l = looks_[index(x, y)];
        unsigned unlike = 0;
        for (int k = 0, dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx == 0 && dy == 0) continue;
                const int nx = x + dx, ny = y + dy;
                if (nx >= x0_ && nx < x1_ && ny >= y0_ && ny < y1_ && !alike(looks_[index(nx, ny)], l, threshold))
                    unlike |= 1u << k;
                ++k;
            }
        return unlike;
    }
    static const std::array<double, 256>& decoded() {
        static const std::array<double, 256> table = [] {
            std::array<double, 256> t{};
            for (int k = 0; k < 256; ++k) t[k] = csg::srgb_to_linear(k / 255.0);
            return t;
        }();
        return table;
    }
    std::size_t index(int x, int y) const {
        return std::size_t(y - first_row_) * std::size_t(x1_ - x0_) + std::size_t(x - x0_);
    }
    int x0_, y0_, x1_, y1_;
    int first_row_;  // the first row held
    const SrgbTable& srgb_;
    BigVector<std::uint64_t> looks_;
};

}  // namespace kerf::render
