// What built-in modules remember across calls within one run: the
// appearance scopes around the statement being evaluated, where the scene's
// camera and background were set (each once), the meshes already imported
// and the primitive count (docs/spec.md §8 limit).
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "csg/ghosts.hpp"
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

    // The `%` and `#` ghosts (interpreter/ghosts.cpp). Their statements run
    // before the operations around them have made their nodes, so the
    // transforms around a statement are kept on a stack while its children
    // evaluate (GhostFrame), and each ghost is recorded with the product.
    struct GhostFrame {
        glm::dmat4 m{1.0};           // world_from_child of a transform
        const char* hides = nullptr;  // else: an operation whose ghosts OpenSCAD does not show ("linear_extrude")
    };
    std::vector<GhostFrame> ghost_frames;
    struct Ghost {
        std::uint32_t node;
        csg::GhostKind kind;
        glm::dmat4 world;  // world_from_node
        std::uint32_t color = csg::kNone;  // `%`: the colour around it, into ghost_colors
        SourceLoc loc;
    };
    std::vector<Ghost> ghosts;
    std::vector<csg::Material> ghost_colors;  // the colours around `%` statements

    // OpenSCAD highlights a difference whose minuend is highlighted (its
    // CSGTreeEvaluator): the ghost of a `#` minuend, recorded since `from`,
    // becomes the ghost of the difference made of it.
    void ghost_minuend(std::size_t from, std::uint32_t minuend, std::uint32_t difference) {
        for (std::size_t i = from; i < ghosts.size(); ++i)
            if (ghosts[i].kind == csg::GhostKind::Highlight && ghosts[i].node == minuend) ghosts[i].node = difference;
    }
};

// Keeps a frame on the ghost stack while an operation's children evaluate.
struct GhostFrameScope {
    std::vector<ModuleState::GhostFrame>& stack;
    GhostFrameScope(ModuleState& s, const glm::dmat4& m) : stack(s.ghost_frames) { stack.push_back({m, nullptr}); }
    GhostFrameScope(ModuleState& s, const char* hides) : stack(s.ghost_frames) { stack.push_back({glm::dmat4(1.0), hides}); }
    ~GhostFrameScope() { stack.pop_back(); }
    GhostFrameScope(const GhostFrameScope&) = delete;
    GhostFrameScope& operator=(const GhostFrameScope&) = delete;
};

}  // namespace kerf::eval
