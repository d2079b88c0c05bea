// OpenSCAD's preview modifiers as kerf draws them (docs/openscad.md,
// "Modifiers"): a `%` (background) part is left out of the solid and shown
// as a translucent grey ghost; a `#` (highlight) part stays in the solid and
// is shown once more as a translucent pink ghost. Ghosts are no solids: each
// kind is a csg::Scene of its own (csg::Scene::ghosts) that the renderer
// composites over the image by depth; they cast no shadows and are not in
// `kerf measure` or the AOVs.
#pragma once
#include <cstdint>

#include "csg/scene.hpp"
#include "csg/srgb.hpp"

namespace kerf::csg {

// OpenSCAD 2021.01's preview colours (its renderer.cc colour map):
// background sRGB (180, 180, 180), highlight (255, 81, 81), both at alpha
// 128/255. The ghost's opacity is 1 − transparency.
inline Material ghost_material(GhostKind kind) {
    Material m;
    const double c = kind == GhostKind::Background ? 180.0 / 255 : 81.0 / 255;
    m.color = srgb_to_linear(glm::dvec3(kind == GhostKind::Background ? c : 1.0, c, c));
    m.interior = m.color;
    m.transparency = 1 - 128.0 / 255;
    return m;
}

}  // namespace kerf::csg
