// The farm's command line (docs/farm.md): --frames, --frame, --tile,
// --resume on `kerf render`, and `kerf assemble OUT TILE...`.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace kerf::cli {

// If args[i] is a farm flag, reads it (and its value, advancing i) into o.farm.
bool parse_farm_flag(const std::vector<std::string>& args, std::size_t& i, Options& o);

// Refuses farm flags that contradict each other or the rest of the command
// line (UsageError); call once o.output is final.
void check_farm_options(const Options& o);

// `kerf assemble OUT TILE...` (args[0] is "assemble").
Options parse_assemble(const std::vector<std::string>& args);

}  // namespace kerf::cli
