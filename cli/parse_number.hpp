// Whole numbers on the command line, range-checked with the flag named in
// the error (options.cpp, farm_options.cpp).
#pragma once
#include <charconv>
#include <string>

#include "cli/options.hpp"

namespace kerf::cli {

template <typename Int>
Int parse_int(const std::string& flag, const std::string& text, Int lo, Int hi) {
    Int v{};
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size() || v < lo || v > hi)
        throw UsageError(flag + " expects a whole number from " + std::to_string(lo) + " to " +
                         std::to_string(hi) + ", got '" + text + "'");
    return v;
}

}  // namespace kerf::cli
