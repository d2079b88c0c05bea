// surface()'s files as OpenSCAD 2021.01 reads them: a .dat text file of
// rows of numbers, or a PNG image's luminance. Only the reading is here;
// interpreter/modules/surface.cpp turns the grid into the solid. Problems
// are MeshFormatErrors (mesh_import.hpp) located inside the file; the
// caller prefixes the surface statement's location.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::eval {

// A .dat file: one row of heights per line, numbers separated by spaces or
// tabs; blank lines and lines whose first non-blank is '#' are skipped.
struct DatHeights {
    std::vector<std::vector<double>> rows;  // as written, file order (row i lies at y = i); may be ragged
    std::vector<std::size_t> lines;         // the file line of each row
    // A token that is not a number: OpenSCAD stops reading there, keeping
    // what came before it (that line's numbers too, as a shorter row).
    struct Stop {
        std::size_t line = 0;
        std::string token;
    };
    std::optional<Stop> stop;
};

// Reads `path`. Errors: the file cannot be read or is longer than
// kMaxImportBytes, a height is NaN or infinite (OpenSCAD fails inside CGAL
// on those), more than `max_heights` numbers.
DatHeights read_dat(const std::string& path, std::uint64_t max_heights);

// A PNG image as lodepng hands it to OpenSCAD: 8 bits per channel (16-bit
// samples keep their high byte, fewer bits are scaled up), palette and
// grey expanded to RGB, alpha ignored, and each pixel's luminance
// 0.2126 R + 0.7152 G + 0.0722 B, in 0..255.
struct PngLuminance {
    int width = 0, height = 0;
    std::vector<double> rows;  // row-major, the image's top row first
};

// Reads `path`; an image of more than `max_pixels` pixels is an error
// found from its header, before any pixel is decoded.
PngLuminance read_png_luminance(const std::string& path, std::uint64_t max_pixels);

}  // namespace kerf::eval
