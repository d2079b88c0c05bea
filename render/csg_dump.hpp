// `kerf dump`: the lowered csg::Scene as stable, line-oriented text (format
// documented in docs/dump-format.md). Prints only csg::Scene data.
#pragma once
#include <string>

#include "render/csg_scene.hpp"

namespace kerf::csg {

std::string dump_scene(const Scene& scene);

}  // namespace kerf::csg
