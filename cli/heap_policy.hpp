// How the C library's heap serves a process that renders once and exits
// (docs/performance.md, "One heap for a one-shot render").
#pragma once

namespace kerf::cli {

// Every allocation from one heap that reuses what is freed: big blocks are
// not mapped and unmapped on their own, and threads do not get arenas of
// their own. For every command but `watch` and `view` (`render`, also the
// farm's frames one after another, `check`, `dump`, `measure`, `assemble`),
// which free the interpreter's graph and then allocate the tracer's tables
// and the image: those reuse the graph's pages instead of faulting in fresh
// ones. Not for `watch` and `view`, which live on between renders and
// should give memory back. Call before any thread starts. A freed block
// returns to this heap, not to the system: where the interpreter's page
// thread may run (EvalOptions::populate_ahead).
void one_heap_for_one_shot();

}  // namespace kerf::cli
