// The last of docs/spec.md §8's limits: memory. A script can stay within every
// element limit and still build a list of millions of large lists; capping
// the process's data size turns that into a located "out of memory" error
// (interpreter/eval_stmt.cpp) instead of swapping the machine to a halt or
// waking the kernel's OOM killer.
#pragma once

namespace kerf::cli {

// Lowers RLIMIT_DATA to three quarters of the physical memory unless it is
// already lower (a user's `ulimit -d` wins).
void cap_memory_to_physical();

}  // namespace kerf::cli
