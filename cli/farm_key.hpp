// What identifies a render (docs/farm.md, "Metadata"): written into every
// frame and band as the PNG text chunk "kerf", so `kerf assemble` joins
// only bands of one render and `--resume` skips only finished work.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "csg/scene.hpp"
#include "interpreter/interpreter.hpp"
#include "render/render.hpp"

namespace kerf::cli {

constexpr const char* kFarmKeyword = "kerf";

// A 64-bit hash of everything in `scene` that can change a pixel (leaves,
// the operation tree, materials, meshes, polygons, camera, lights,
// background), by exact bits; source locations are left out.
std::uint64_t scene_hash(const csg::Scene& scene);

// "scene=HASH width=W height=H seed=S options=..." where options lists the
// sampling, precision and crop settings, each exactly, and --facets unless
// auto (bands cut in other modes are refused together even where the scene
// has no curve to tell them apart).
std::string render_key(const csg::Scene& scene, const render::RenderOptions& ro, FacetMode facets = FacetMode::Auto);

// The rows [y0, y1) of band k of n of an image `height` rows tall.
inline std::array<int, 2> band_rows(int height, int k, int n) {
    return {int(std::int64_t(k) * height / n), int(std::int64_t(k + 1) * height / n)};
}

// "name=value" words back into a map; words without '=' are ignored.
std::map<std::string, std::string> parse_key(const std::string& text);

}  // namespace kerf::cli
