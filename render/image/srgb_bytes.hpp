// Linear float -> 8-bit sRGB code by the one curve of csg/srgb.hpp, shared by
// the image writer (encoding a float image) and the renderer (storing bytes
// directly for 8-bit output), so both give the same byte for the same float.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "csg/srgb.hpp"

namespace kerf::render {

// The 8-bit sRGB code of a linear value without a pow per channel: code k
// starts where the encoded value reaches (k - 0.5) / 255, so counting the
// thresholds at or below the value gives round(255 * encode(value)). A table
// over 2^14 equal bins gives the count at the bin's start; the steepest part
// of the curve (near 0) crosses at most one more threshold within a bin.
struct SrgbTable {
    static constexpr int kBins = 1 << 14;
    std::array<float, 256> threshold{};     // [k]: where code k + 1 starts; [255] = +inf
    std::array<std::uint8_t, kBins> first{};  // code at the start of each bin
    SrgbTable() {
        for (int k = 1; k <= 255; ++k) {
            const double e = (k - 0.5) / 255.0;
            threshold[k - 1] = float(csg::srgb_to_linear(e));
        }
        threshold[255] = std::numeric_limits<float>::infinity();
        int code = 0;
        for (int b = 0; b < kBins; ++b) {
            while (float(b) / kBins >= threshold[code]) ++code;
            first[b] = std::uint8_t(code);
        }
        // srgb_byte steps at most one threshold past a bin's first code: true
        // when no bin holds two thresholds (the narrowest gap, near 0, is
        // 1/(255·12.92) ≈ 3.0e-4 > 1/2^14 ≈ 6.1e-5).
        for (int k = 0; k + 1 < 255; ++k)
            if (int(threshold[k] * kBins) == int(threshold[k + 1] * kBins)) std::abort();
    }
};

inline const SrgbTable& srgb_table() {
    static const SrgbTable table;
    return table;
}

// The table is passed in, so the loop over millions of channels carries no
// static-initialisation guard; one threshold step suffices (see SrgbTable).
inline std::uint8_t srgb_byte(const SrgbTable& table, float linear) {
    if (!(linear > 0)) return 0;  // NaN too
    if (linear >= 1) return 255;
    const int code = table.first[int(linear * SrgbTable::kBins)];
    return std::uint8_t(code + (linear >= table.threshold[code] ? 1 : 0));
}

}  // namespace kerf::render
