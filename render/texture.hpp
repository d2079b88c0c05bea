// Image textures (docs/language.md, "Image textures"): reading image files
// once per file (8-bit PNG by image/png_read.hpp, EXR, TIFF, JPEG by their
// own libraries, other formats through OpenImageIO: image/image_modules.hpp), and the colour an image gives a point
// of pattern space under its mapping. Pure functions of the point, so a
// picture is the same for any thread count.
#pragma once
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "csg/texture.hpp"

namespace kerf::render {

// A csg::TextureReader: decodes `path` (PNG, EXR, TIFF, JPEG, or any format OpenImageIO reads;
// integer formats are taken as sRGB and decoded to linear, float formats as
// linear), keeping it for the life of the process so a file named by many
// materials, or by the scripts of a --watch session, is read once. A file
// changed since is read again (its modification time and size are the key).
std::shared_ptr<const csg::Texture> read_texture(const std::string& path, std::string& why);

// Image coordinates (u, v) of pattern-space point q (csg::TextureMapping).
glm::dvec2 texture_uv(csg::TextureMapping mapping, const glm::dvec3& q);

// The colour at (u, v): u wraps (the image repeats across), v wraps for the
// planar and cylindrical mappings and is clamped to the poles' rows for the
// spherical one. Nearest: the pixel whose cell holds (u, v), pixel (i, j)
// covering u ∈ [i/W, (i+1)/W), v ∈ (1 − (j+1)/H, 1 − j/H]. Bilinear: the
// four nearest pixel centres blended, so a pixel's centre shows its colour
// exactly.
glm::dvec3 texture_color(const csg::Texture& t, csg::TextureMapping mapping, bool bilinear, const glm::dvec2& uv);

}  // namespace kerf::render
