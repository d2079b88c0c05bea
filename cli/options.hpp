// The kerf command line (docs/spec.md §7): parsed into plain data, no side effects.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "render/render.hpp"

namespace kerf::cli {

enum class Command { Render, Watch, Check, Dump, Help, Version };

// The libraries' own option structs, filled from the arguments: the command
// line never mirrors what the libraries already define.
struct Options {
    Command command = Command::Help;
    std::string scene;   // "-": standard input
    std::string base;    // --base: folder that includes of a scene from standard input resolve against
    std::string output;  // after parsing: SCENE.png beside the scene unless -o; "-": PNG to standard output
    bool stats = false;
    bool progress = true;  // --no-progress: no progress line even on a terminal
    EvalOptions eval;
    render::RenderOptions render;
};

// A bad command line: printed as "kerf: error: MESSAGE", exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Options parse_options(const std::vector<std::string>& args);
const char* usage_text();

}  // namespace kerf::cli
