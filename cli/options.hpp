// The kerf command line (docs/spec.md §7): parsed into plain data, no side effects.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/measure/measure.hpp"
#include "render/render.hpp"

namespace kerf::cli {

enum class Command { Render, Watch, View, Check, Dump, Measure, Assemble, Help, Version };

// Rendering on many machines (docs/farm.md): an animation's frames, an
// image's horizontal bands.
struct FarmOptions {
    int frames = 0;       // --frames N; 0: one image
    int frame = 0;        // --frame I, 1..N; 0: every frame
    int tiles = 0;        // --tile K/N: N; 0: the whole image
    int tile = 0;         // K, 0..N-1
    bool resume = false;  // skip outputs already written by the same render
    bool any() const { return frames > 0 || tiles > 0; }
};

// The libraries' own option structs, filled from the arguments: the command
// line never mirrors what the libraries already define.
struct Options {
    Command command = Command::Help;
    std::string scene;   // "-": standard input
    std::string base;    // --base: folder that includes of a scene from standard input resolve against
    std::string output;  // after parsing: SCENE.png beside the scene unless -o; "-": PNG to standard output
    bool stats = false;
    bool progress = true;  // --no-progress: no progress line even on a terminal
    bool progressive = false;  // --progressive: the path integrator writes OUT after every pass
    FarmOptions farm;
    std::vector<std::string> tiles;  // assemble: the band files (output: OUT)
    EvalOptions eval;
    Look look = Look::Studio;  // --look: what a script without camera, lights or background gets
    bool ghosts = true;        // --no-ghosts: `%` and `#` parts drawn as OpenSCAD's render does (csg/ghosts.hpp)
    render::RenderOptions render;
    render::MeasureOptions measure;  // kerf measure: resolution; threads and precision as for render
    std::string host = "127.0.0.1";  // kerf view: --host, a loopback address only
    int port = 0;                    // kerf view: --port; 0: a free one
};

// A bad command line: printed as "kerf: error: MESSAGE", exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Options parse_options(const std::vector<std::string>& args);
const char* usage_text();

}  // namespace kerf::cli
