// Linear float -> 8-bit sRGB code by the one curve of csg/srgb.hpp, shared by
// the image writer (encoding a float image) and the renderer (storing bytes
// directly for 8-bit output), so both give the same byte for the same float.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "csg/srgb.hpp"

namespace kerf::render {

// The 8-bit sRGB code of a linear value without a pow per channel: code k
// starts where the encoded value reaches (k - 0.5) / 255, so counting the
// thresholds at or below the value gives round(255 * encode(value)). A table
// over bins of the float's bits (its exponent and top kMantissaBits mantissa
// bits, from kLow to 1) gives the count at the bin's start; no bin holds two
// thresholds, so one more comparison finishes it. Bins by bits are
// relatively equal, as the thresholds are spaced (at least 0.89 % of the
// value apart, near 1): 1.6 KB of table, where 2^14 equal bins took 16 KB
// that the tracer's data pushed out of the L1 cache between pixels.
struct SrgbTable {
    static constexpr int kMantissaBits = 7;  // bins 2^-7 of their value wide at most
    static constexpr std::uint32_t kLowBits = 114u << 23;  // the bits of kLow = 2^-13
    static constexpr std::uint32_t kOneBits = 127u << 23;  // the bits of 1.0f
    static constexpr int kShift = 23 - kMantissaBits;
    static constexpr int kBins = int((kOneBits - kLowBits) >> kShift);  // 13 octaves of 128
    static constexpr float kLow = 0x1p-13f;  // below the first threshold (1.5e-4): code 0
    std::array<float, 256> threshold{};     // [k]: where code k + 1 starts; [255] = +inf
    std::array<std::uint8_t, kBins> first{};  // code at the start of each bin
    static std::uint32_t bits(float f) {
        std::uint32_t b;
        std::memcpy(&b, &f, sizeof b);
        return b;
    }
    static int bin(float f) { return int((bits(f) - kLowBits) >> kShift); }
    SrgbTable() {
        for (int k = 1; k <= 255; ++k) {
            const double e = (k - 0.5) / 255.0;
            threshold[k - 1] = float(csg::srgb_to_linear(e));
        }
        threshold[255] = std::numeric_limits<float>::infinity();
        int code = 0;
        for (int b = 0; b < kBins; ++b) {
            float start;
            const std::uint32_t start_bits = kLowBits + (std::uint32_t(b) << kShift);
            std::memcpy(&start, &start_bits, sizeof start);
            while (start >= threshold[code]) ++code;
            first[b] = std::uint8_t(code);
        }
        // srgb_byte steps at most one threshold past a bin's first code:
        // true when every threshold is above kLow and no bin holds two.
        if (!(threshold[0] > kLow)) std::abort();
        for (int k = 0; k + 1 < 255; ++k)
            if (bin(threshold[k]) == bin(threshold[k + 1])) std::abort();
    }
};

inline const SrgbTable& srgb_table() {
    static const SrgbTable table;
    return table;
}

// The table is passed in, so the loop over millions of channels carries no
// static-initialisation guard; one threshold step suffices (see SrgbTable).
inline std::uint8_t srgb_byte(const SrgbTable& table, float linear) {
    if (!(linear >= SrgbTable::kLow)) return 0;  // NaN too
    if (linear >= 1) return 255;
    const int code = table.first[SrgbTable::bin(linear)];
    return std::uint8_t(code + (linear >= table.threshold[code] ? 1 : 0));
}

}  // namespace kerf::render
