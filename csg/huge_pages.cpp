#include "csg/huge_pages.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace kerf::csg {

namespace {

// Off unless KERF_HUGE_PAGES=1. On this project's virtual machines (free
// page reporting: the guest hands whole free 2 MiB blocks back to the
// host) a huge page is exactly such a block, and its first touch waits for
// the host: spheres_1000000 at 1024^2 took 2.4-3.8 s with the hint against
// 0.91-0.95 s without, spheres_100000 at 2048^2 355 ms against 259 ms
// (runs 1.5 s apart, as a benchmark or an editor's renders come;
// docs/performance.md "Huge pages off by default"). Back to back, or on
// bare metal, the hint saves 4 KiB faults: there it may be turned on.
bool wanted() {
    static const bool on = [] {
        const char* e = std::getenv("KERF_HUGE_PAGES");
        return e && std::strcmp(e, "1") == 0;
    }();
    return on;
}

}  // namespace

void advise_huge_pages(void* data, std::size_t bytes) {
    if (!wanted()) return;
#if defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = kHugePage;
    if (bytes < 2 * kHuge) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t lo = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t hi = (begin + bytes) & ~(kHuge - 1);
    if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);  // a hint: failure is fine
#else
    (void)data;
    (void)bytes;
#endif
}

bool populate_pages(void* data, std::size_t bytes) {
#if defined(__linux__)
    constexpr int kPopulateWrite = 23;  // MADV_POPULATE_WRITE (older headers lack the name)
    constexpr std::uintptr_t kPage = 4096;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t lo = begin & ~(kPage - 1);  // madvise takes whole pages
    const std::uintptr_t hi = (begin + bytes + kPage - 1) & ~(kPage - 1);
    if (bytes > 0 && madvise(reinterpret_cast<void*>(lo), hi - lo, kPopulateWrite) != 0) return errno != EINVAL;
    return true;
#else
    (void)data;
    (void)bytes;
    return false;
#endif
}

}  // namespace kerf::csg
