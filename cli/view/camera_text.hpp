// A camera as text, both ways: the query the page sends after each orbit,
// pan or zoom (`POST /camera?position=x,y,z&look_at=...&up=...&fov=F`, or
// `&height=H` for an orthographic view), and the `camera(...)` statement
// the page's "Copy camera" button gives (docs/language.md, scene
// statements), which reproduces the view when pasted into the scene.
#pragma once
#include <map>
#include <optional>
#include <string>

#include "csg/scene.hpp"

namespace kerf::view {

// The camera a query names, or nullopt and `*error` saying why: every
// number finite and within csg::kRenderableRange, the position apart from
// look_at, up not along the view, 0 < fov < 180, height > 0.
std::optional<csg::Camera> camera_from_query(const std::multimap<std::string, std::string>& params, std::string* error);

// `camera(position = [..], look_at = [..], up = [..], fov = F);` (or
// `projection = "orthographic", height = H`), numbers exact.
std::string camera_statement(const csg::Camera& c);

// The camera as a JSON object for the page (the same fields).
std::string camera_json(const csg::Camera& c);

}  // namespace kerf::view
