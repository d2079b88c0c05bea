// What built-in modules remember across calls within one run: the
// appearance scopes around the statement being evaluated, where the scene's
// camera and background were set (each once), the meshes already imported
// and the primitive count (docs/spec.md §8 limit).
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "csg/scene.hpp"
#include "grammar/source.hpp"

namespace kerf::eval {

struct ModuleState {
    // The innermost material, so color() inside material() keeps the
    // material's other parameters.
    struct CurrentMaterial {
        csg::Material m;
        bool interior_set = false;
        bool color2_set = false;  // else a pattern blends with black, with a warning
    };
    std::vector<CurrentMaterial> materials;
    const SourceLoc* camera_loc = nullptr;
    const SourceLoc* background_loc = nullptr;
    std::unordered_map<std::string, std::uint32_t> imported;  // surface(): "options|path" → mesh index: a loop reads once
    std::unordered_map<std::string, std::vector<std::uint32_t>> imported_parts;  // import(): "solid|path" → its parts' meshes
    std::uint64_t primitives = 0;
};

}  // namespace kerf::eval
