// libFuzzer entry point: arbitrary bytes are parsed, evaluated and lowered
// to csg::Scene (what `kerf check` does) under small limits, so each input finishes in milliseconds and a
// runaway loop or recursion surfaces as the located limit error it must be.
// Every input runs twice: as a strict `.sdl` script and as a lenient `.scad`
// file (OpenSCAD's dialect: undef and warnings where `.sdl` stops), since
// the two take different paths through evaluation.
// A scene that lowers is then rendered, 8×6 pixels on one thread with the
// default adaptive sampling, so tracer crashes are found here, not by users:
// a render must never throw for a scene lowering accepted.
// User-caused failures (SourceError, IoError) are the expected outcome for
// garbage; anything else escaping — another exception type, a crash, a
// sanitizer report, a timeout — is a finding.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "grammar/parser.hpp"
#include "grammar/source.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/render.hpp"
#include "tests/fuzz/fuzz_limits.hpp"

namespace {

kerf::EvalOptions small_limits() {
    kerf::EvalOptions o;
    o.limits = kerf::test::fuzz_limits();
    o.echo = [](const std::string&) {};  // keep the fuzzer's output readable
    return o;
}

void run(const std::uint8_t* data, std::size_t size, const char* path) {
    static const kerf::EvalOptions options = small_limits();
    auto file = std::make_shared<kerf::SourceFile>();
    // A path inside a folder with no scene files, so relative include/use
    // resolve to nothing (a missing file) rather than to the corpus.
    file->path = path;
    file->text.assign(reinterpret_cast<const char*>(data), size);
    try {
        // Lowering sees only graphs the evaluator accepted, so fuzzing it
        // behind evaluation finds what a real script can reach.
        const kerf::csg::Scene scene = kerf::lower_to_csg(kerf::evaluate_source(std::move(file), options).graph);
        kerf::render::RenderOptions r;
        r.width = 8;
        r.height = 6;
        r.threads = 1;
        r.adaptive = true;
        kerf::render::render(scene, r);  // any exception escapes: a finding
    } catch (const kerf::SourceError&) {
    } catch (const kerf::IoError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    run(data, size, "/nonexistent-kerf-fuzz/input.sdl");
    run(data, size, "/nonexistent-kerf-fuzz/input.scad");
    return 0;
}
