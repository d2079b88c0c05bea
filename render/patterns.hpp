// Procedural patterns (docs/language.md, "Patterns"): a value in [0, 1] at a
// point of pattern space, a pure function of the point (no seed, no state),
// so a picture is the same for any thread count. The shader blends a
// material's color (0) and color2 (1) by it.
#pragma once
#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/texture.hpp"

namespace kerf::render {

// checker: (⌊x⌋ + ⌊y⌋ + ⌊z⌋) mod 2 — unit cubes, the one holding (0.5, 0.5, 0.5) is 0.
// stripes: ⌊x⌋ mod 2 — slabs one unit thick across x, period 2.
// gradient: x − ⌊x⌋ — a ramp from 0 to 1 across each unit of x.
// The floors are taken at x + 1e-6 so a face lying on a cell boundary
// (a ground plane at z = 0) falls in one cell instead of speckling.
// noise: smooth lattice value noise, four octaves (a convex mix, so in [0, 1]).
// marble: ½ + ½·sin(π·(x + 4·noise)) — veins across x, bent by the noise.
// wood: rings about the z axis, √(x² + y²) + ½·noise, fractional part.
double pattern_value(csg::Pattern pattern, const glm::dvec3& q);

// The value noise alone (lattice values hashed from integer coordinates,
// blended by quintic fades): one octave, in [0, 1].
double lattice_noise(const glm::dvec3& q);

// The material's colour at world point p on a solid whose leaf maps world to
// its material() call's coordinates by material_from_world
// (Scene::material_frames[leaf.material_frame]); an image texture's
// colour replaces color (texture.hpp).
inline glm::dvec3 pattern_color(const csg::Material& m, const csg::Affine& material_from_world, const glm::dvec3& p) {
    if (m.pattern == csg::Pattern::None) return m.color;
    const glm::dvec3 q = m.pattern_from_material.point(material_from_world.point(p));
    if (m.pattern == csg::Pattern::Image)
        return m.texture ? texture_color(*m.texture, m.mapping, m.bilinear, texture_uv(m.mapping, q)) : m.color;
    const double v = pattern_value(m.pattern, q);
    return m.color + v * (m.color2 - m.color);
}

// The material of a leaf without one (a scene without materials): the
// default light grey. At namespace scope, not a function's static, so a
// shading point does not test an initialisation guard.
inline const csg::Material kFallbackMaterial{};

// The material of `leaf`.
inline const csg::Material& leaf_material(const csg::Scene& scene, std::uint32_t leaf) {
    const std::uint32_t i = scene.leaves[leaf].material;
    return i < scene.materials.size() ? scene.materials[i] : kFallbackMaterial;
}

// The colour a surface of material m (the material of leaf `mat_leaf`)
// shows at p: a cut face the solid's interior colour, unpatterned; else
// the pattern's or texture's colour there.
inline glm::dvec3 surface_albedo(const csg::Scene& scene, const csg::Material& m, std::uint32_t mat_leaf, bool cut,
                                 const glm::dvec3& p) {
    if (cut) return m.interior;
    return pattern_color(m, scene.material_frames[scene.leaves[mat_leaf].material_frame], p);
}

}  // namespace kerf::render
