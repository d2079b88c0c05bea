#include "cli/memory_cap.hpp"

#include <sys/resource.h>
#include <unistd.h>

namespace kerf::cli {

void cap_memory_to_physical() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return;
    const rlim_t cap = rlim_t(pages) / 4 * 3 * rlim_t(page);
    rlimit rl{};
    if (::getrlimit(RLIMIT_DATA, &rl) != 0) return;
    if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur <= cap) return;
    rl.rlim_cur = cap;
    ::setrlimit(RLIMIT_DATA, &rl);  // best effort: without it the old behaviour stays
}

}  // namespace kerf::cli
