// Image textures in the contract (docs/language.md, "Image textures"): the
// decoded pixels a material points at, and the hook through which the
// interpreter reads image files. The interpreter cannot link the image
// libraries (render/ loads them as modules, image/image_modules.hpp), so the program that
// renders installs the reader (render::read_texture) before evaluating.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace kerf::csg {

// How a point of pattern space becomes image coordinates (u, v) in [0, 1]²,
// u across the image left to right, v from the bottom row up.
enum class TextureMapping : std::uint8_t {
    Planar,       // u = x, v = y: the image fills the unit square of the xy plane, repeated
    Spherical,    // u = longitude/2π from +x counter-clockwise about z, v = ½ + latitude/π
    Cylindrical,  // u as spherical, v = z: one image per unit of height, repeated
};

struct Texture {
    std::string path;          // as resolved, for messages and the dump
    int width = 0, height = 0;
    std::vector<float> rgb;    // linear RGB, rows top to bottom, 3 floats per pixel
    std::uint64_t digest = 0;  // of the pixels: two files with the same pixels share it
};

// Reads an image file; on failure returns null with `why` set ("no such file").
using TextureReader = std::shared_ptr<const Texture> (*)(const std::string& path, std::string& why);
void set_texture_reader(TextureReader reader);
TextureReader texture_reader();  // null until set

}  // namespace kerf::csg
