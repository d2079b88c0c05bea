// `kerf dump`: the lowered csg::Scene as stable, line-oriented text (format
// documented in docs/dump-format.md). Prints only csg::Scene data.
#pragma once
#include <iosfwd>
#include <string>

#include "csg/scene.hpp"

namespace kerf::csg {

std::string dump_scene(const Scene& scene);

// The same text, streamed (for `kerf dump` on very large scenes).
void dump_scene(const Scene& scene, std::ostream& out);

}  // namespace kerf::csg
