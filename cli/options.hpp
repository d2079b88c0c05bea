// The kerf command line (docs/spec.md §7): parsed into plain data, no side effects.
#pragma once
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/interpreter.hpp"

namespace kerf::cli {

enum class Command { Render, Check, Dump, Help, Version };
enum class AovKind { None, Depth, Normal, Hits };

struct Options {
    Command command = Command::Help;
    std::string scene;
    std::string output;  // empty: SCENE.png beside the scene
    int width = 800, height = 600;
    int spp = 1;
    int threads = 0;  // 0: all cores
    bool preview = false;
    bool stats = false;
    bool double_precision = true;
    std::uint64_t seed = 0;
    AovKind aov = AovKind::None;
    std::optional<std::array<int, 4>> crop;
    EvalOptions eval;
};

// A bad command line: printed as "kerf: error: MESSAGE", exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Options parse_options(const std::vector<std::string>& args);
const char* usage_text();

}  // namespace kerf::cli
