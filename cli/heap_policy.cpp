#include "cli/heap_policy.hpp"

#include <malloc.h>

namespace kerf::cli {

// glibc serves a block above its mmap threshold (128 KiB, rising to at most
// 32 MiB) with a mapping of its own and unmaps it when freed; a later block
// then takes fresh pages, each a page fault (on this VM ~1.5 µs a 4 KiB
// page: the host hands freed memory back and supplies it again). A
// 10^5-sphere render took ~25,000 faults; on one heap ~19,400, and ~20 ms
// less CPU. Threads share the main arena: kerf's hot loops do not allocate
// (the tracer's, lowering's and the encoder's work in preallocated slots),
// so its lock is not contended. RLIMIT_DATA (memory_cap.cpp) bounds the
// heap as it bounded the mappings, and out-of-memory is still bad_alloc.
// A freed block goes back to the heap, not to the system (only the heap's
// top is trimmed): the interpreter's page thread (csg/populate_ahead.hpp)
// runs only here. Not trimming at all cost the 10^6-sphere render 44 MB of
// peak (docs/performance.md).
void one_heap_for_one_shot() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_MAX, 0);   // no block on a mapping of its own
    mallopt(M_ARENA_MAX, 1);  // every thread on the main heap
#endif
}

}  // namespace kerf::cli
