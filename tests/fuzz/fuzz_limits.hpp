// The small limits the fuzzer evaluates under (tests/fuzz/fuzz_eval.cpp), so
// each input finishes in milliseconds and a runaway loop or recursion ends
// in its located limit error. The golden scripts replay the fuzzer's
// regressions under the same limits (tests/scripts/, `// limits: fuzz`).
#pragma once
#include "interpreter/interpreter.hpp"

namespace kerf::test {

inline EvalLimits fuzz_limits() {
    EvalLimits l;
    l.call_depth = 200;
    l.nesting = 64;
    l.loop_iterations = 100'000;
    l.list_elements = 100'000;
    l.primitives = 10'000;
    l.steps = 100'000;
    l.echo_bytes = 100'000;  // echo is formatted even when discarded: 5*10^7 bytes took ~8 s under ASan
    return l;
}

}  // namespace kerf::test
