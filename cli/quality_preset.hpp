// --quality draft|good|final (docs/quality.md "Presets"): one word for a
// bundle of sampling knobs, picked from bench/quality_curves.py's measured
// time/error curves. `good` is the defaults, so a command line without
// --quality renders the same bytes; an explicit knob beside a preset wins.
#pragma once
#include <string>

namespace kerf::cli {

struct QualityPreset {
    const char* name;
    int aa_samples;         // --aa-samples (adaptive anti-aliasing)
    double aa_threshold;    // --aa-threshold
    int max_reflect_depth;  // --max-depth (Whitted)
    int path_spp;           // --spp under --integrator path
    int max_path_depth;     // --max-depth under --integrator path
};

inline constexpr QualityPreset quality_presets[] = {
    {"draft", 4, 0.1, 2, 16, 8},
    {"good", 16, 0.05, 4, 64, 16},
    {"final", 64, 0.02, 8, 256, 16},
};

// nullptr for an unknown name.
inline const QualityPreset* find_quality_preset(const std::string& name) {
    for (const auto& p : quality_presets)
        if (name == p.name) return &p;
    return nullptr;
}

}  // namespace kerf::cli
