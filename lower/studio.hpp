// The studio look (docs/spec.md §12 "Default look"): what a script without a
// camera, lights or background gets unless `--look plain` asks for the §6
// defaults of defaults.hpp — a camera that fills 80 % of the frame with the
// model, a soft key light and a shadowless fill, a ground that catches the
// key's shadow, a neutral background.
#pragma once
#include <vector>

#include "csg/scene.hpp"
#include "grammar/source.hpp"

namespace kerf {

// The share of the image the model's bounding box spans, in the direction
// where it is the tighter fit (docs/language.md, "The default look").
inline constexpr double kStudioFill = 0.8;
// Linear RGB of the studio background (sRGB 0.735, a light neutral grey).
inline constexpr double kStudioBackground = 0.5;

// A perspective camera (fov 40°, up +Z) looking from the [1, -1, 0.8]
// direction, placed so that the projections of the box's eight corners span
// exactly kStudioFill of the image's width or of its height (whichever is
// tighter for an image `aspect` = width / height) and are centred in the
// other. The size checks of default_camera apply (a SourceError at `loc`);
// a box with no extent at all is framed as default_camera frames it.
csg::Camera studio_camera(const csg::Aabb& frame, double aspect, const SourceLoc& loc);

// The key light (spherical, radius 0.7 of the box's bounding-sphere radius,
// 16 shadow rays: soft shadows) above and to the left of the view, and a
// shadowless fill from the right; placed round the box from the camera's
// horizontal direction, so that a user's camera keeps them in front.
std::vector<csg::Light> studio_lights(const csg::Camera& camera, const csg::Aabb& frame);

}  // namespace kerf
