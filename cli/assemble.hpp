// `kerf assemble OUT TILE...` (docs/farm.md): the bands of one `--tile`
// render joined into the file a single render writes, byte for byte.
#pragma once
#include <stdexcept>

#include "cli/options.hpp"

namespace kerf::cli {

// Bands that cannot be joined: missing, duplicated, from another render, or
// not bands at all. One line; exit status 2, and OUT is not touched.
class TileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads and checks every band in o.tiles, then writes o.output; returns
// the exit status (3 when OUT cannot be written).
int assemble(const Options& o);

}  // namespace kerf::cli
