// How many CPUs this process may run on: its affinity mask (taskset, a
// container's cpuset), not the machine's count. Lowering's threads and the
// interpreter's page thread ask before starting helpers.
#pragma once
#include <algorithm>
#include <thread>

#include <sched.h>

namespace kerf::csg {

// At least 1.
inline unsigned usable_cpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) return unsigned(std::max(1, CPU_COUNT(&set)));
    return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace kerf::csg
