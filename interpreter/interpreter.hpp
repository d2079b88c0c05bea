// Entry point of the interpreter stage: a parsed script in, a scene graph out.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/parser.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf {

// docs/spec.md §8 limits; every one is overridable from the command line and ends in
// a located error when exceeded.
struct EvalLimits {
    // 0: the dialect's (call_depth_limit): kerf's 1,000, or 10,000 in
    // OpenSCAD's, whose functions recurse past 5,000 calls (2021.01 measured).
    std::uint64_t call_depth = 0;
    std::uint64_t nesting = 256;             // source nesting (passed to the parser)
    std::uint64_t loop_iterations = 10'000'000;  // total over the run
    std::uint64_t list_elements = 10'000'000;    // per list
    std::uint64_t primitives = 1'000'000;
    std::uint64_t steps = 100'000'000;       // calls + instantiations + iterations
    std::uint64_t tail_calls = 1'000'000;    // a function calling itself in tail position, per chain (OpenSCAD's)
    // Bytes of echo output over the run: a recursion that echoes a value
    // growing with each call (OpenSCAD's issue4172 test) prints the square
    // of its depth, 144 MB at 1,000 calls and 14 GB at 10,000.
    std::uint64_t echo_bytes = 50'000'000;
};

// The call depth a run allows: the limit given, or the dialect's default.
inline std::uint64_t call_depth_limit(const EvalLimits& limits, bool lenient) {
    return limits.call_depth ? limits.call_depth : lenient ? 10'000 : 1'000;
}

// Which rules a run follows (docs/openscad.md): kerf's strict rules, or
// OpenSCAD's lenient ones (a name bound twice takes the last value, an
// unknown name or a failed operation is undef and a warning). Auto picks by
// the main file's extension: `.scad` is lenient, everything else strict.
enum class Dialect { Auto, Strict, Lenient };

// --facets (docs/spec.md §11, docs/openscad.md "Facets"): what `$fn`, `$fa`
// and `$fs` do. Auto: an explicit `$fn` from 3 to 12 on a circle or
// cylinder call makes OpenSCAD's regular polygon, every other curve is
// exact. Exact: every curve is exact. OpenScad: every curve OpenSCAD 2021
// facets is cut into its facets, as OpenSCAD cuts it (the printed part).
enum class FacetMode { Auto, Exact, OpenScad };

struct EvalOptions {
    EvalLimits limits;
    Dialect dialect = Dialect::Auto;
    // --werror: each warning is reported as an error ("... [--werror]") and
    // the run fails as at an error, after the whole script has run.
    bool werror = false;
    std::vector<std::string> include_dirs;   // -I, searched after the including file's folder
    std::string stdlib_dir;                  // searched last; empty = KERF_STDLIB_DIR
    std::vector<std::pair<std::string, std::string>> defines;  // -D name=value (value is an expression)
    std::function<void(const std::string&)> echo;  // receives "ECHO: ..." lines; default: stderr
    // --curve-tolerance: how far a flattened curve (a glyph's Béziers) may
    // be from the true one, as a fraction of the shape's size.
    double curve_tolerance = 1e-4;
    FacetMode facets = FacetMode::Auto;  // --facets
    // --integrator path: the path tracer has no ambient term, so
    // ambient_occlusion() is ignored there, with a warning.
    bool path_integrator = false;
    // Receives every file the run depends on, as it is looked up: the main
    // file, each file an include, use or import resolved to, and each place
    // searched before it (a file created there would be found instead).
    // Also for a run that stops at an error, up to the error: `kerf watch`
    // watches exactly these.
    std::function<void(const std::string& path)> on_dependency;
    // Lowering's hull(), minkowski() and resize() (kerf::resolve_geometry_ops,
    // lower/geometry_ops.hpp): projection() runs it on a subtree holding
    // them and projects the ordinary nodes it gives back. Handed in by the
    // caller (the CLI, the tests), as the interpreter does not include
    // lowering (docs/architecture.md, "Layers"); unset, such a projection is
    // an error.
    std::function<bool(const graph::SceneGraph&, graph::SceneGraph&)> resolve_geometry_ops;
    // A second thread faults the node arena's pages in ahead of evaluation
    // (csg/populate_ahead.hpp); the builder stops it before any watched
    // array moves, and, as a second line, the CLI sets this only where a
    // freed block returns to the process's heap (cli/heap_policy.hpp; the
    // tests rely on the stop alone). Not with --threads 1 (`threads`: 0 is
    // all cores) or on one usable CPU.
    bool populate_ahead = false;
    unsigned threads = 0;
};

// A -D value that does not parse, evaluate or name a top-level binding: a
// command-line error (the CLI exits 2), reported as "<command line>: error:".
class DefineError : public SourceError {
public:
    explicit DefineError(std::string message) : SourceError(SourceLoc{}, std::move(message)) {}
};

struct EvalResult {
    graph::SceneGraph graph;
    std::vector<Diagnostic> warnings;
};

// Parse and evaluate a script file. Throws IoError (unreadable file) or
// SourceError (first syntax or evaluation error, located; DefineError for a
// bad -D value).
EvalResult evaluate_file(const std::string& path, const EvalOptions& options = {});
EvalResult evaluate_source(std::shared_ptr<const SourceFile> file, const EvalOptions& options = {});

// True when a run of `main_path` under `dialect` follows OpenSCAD's rules.
bool is_lenient(Dialect dialect, std::string_view main_path);

}  // namespace kerf
