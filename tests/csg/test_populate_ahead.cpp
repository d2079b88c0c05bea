// csg::PopulateAhead: the pages just past a growing array's end are faulted
// in by its thread, and never more than kAhead elements past the end the
// writer reported (the array's reservation is address space only and may
// be huge). Judged by mincore(): which pages the kernel has backed.
#include <catch2/catch.hpp>

#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#include "csg/huge_pages.hpp"
#include "csg/populate_ahead.hpp"

using kerf::csg::PopulateAhead;

namespace {

constexpr std::size_t kPage = 4096;

// Whether the page holding byte `at` of v's buffer is backed.
bool resident(const std::vector<std::uint64_t>& v, std::size_t at) {
    const auto p = (reinterpret_cast<std::uintptr_t>(v.data()) + at) & ~(kPage - 1);
    unsigned char in = 0;
    REQUIRE(mincore(reinterpret_cast<void*>(p), kPage, &in) == 0);
    return in & 1;
}

}  // namespace

TEST_CASE("PopulateAhead populates a bounded distance past the reported end, and stops", "[memory]") {
    // 64 MB: above malloc's mmap threshold, so fresh pages, none backed.
    std::vector<std::uint64_t> v;
    v.reserve(std::size_t(8) << 20);
    // 4 KiB pages: with transparent huge pages "always" the first touch
    // backs a whole 2 MiB, and "nothing past the distance" would see it.
    madvise(reinterpret_cast<void*>((reinterpret_cast<std::uintptr_t>(v.data()) + kPage - 1) & ~(kPage - 1)),
            v.capacity() * sizeof(std::uint64_t) - kPage, MADV_NOHUGEPAGE);
    if (!kerf::csg::populate_pages(v.data(), 1)) {
        WARN("the kernel has no MADV_POPULATE_WRITE: nothing to test");
        return;
    }
    const std::size_t bytes = v.capacity() * sizeof(std::uint64_t);
    v.push_back(1);
    PopulateAhead ahead;
    ahead.enable();
    PopulateAhead::Watch w;
    ahead.watch(w, v);
    CHECK(w.slot == 0);
    for (std::uint64_t i = 0; i < 100000; ++i) {
        v.push_back(i);
        ahead.advance(w, v);
    }
    // The last report was at the last multiple of kStep: the thread fills to
    // there plus kAhead elements. Wait (bounded) for it.
    const std::size_t reported = v.size() / PopulateAhead::kStep * PopulateAhead::kStep;
    const std::size_t end = (reported + PopulateAhead::kAhead) * sizeof(std::uint64_t);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!resident(v, end - 1) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ahead.stop();
    for (std::size_t at = v.size() * sizeof(std::uint64_t); at < end; at += kPage) CHECK(resident(v, at));
    // Nothing past the distance: the rest of the 64 MB stays address space.
    std::size_t beyond = 0;
    for (std::size_t at = (end + kPage - 1) / kPage * kPage + kPage; at < bytes; at += kPage) beyond += resident(v, at);
    CHECK(beyond == 0);
}

TEST_CASE("PopulateAhead not enabled, or asked for a small array, starts nothing", "[memory]") {
    std::vector<std::uint64_t> v(10);
    PopulateAhead ahead;
    ahead.enable();
    PopulateAhead::Watch w;
    ahead.watch(w, v);  // no room past the end worth a thread
    CHECK(w.slot == -1);
    std::vector<std::uint64_t> big;
    big.reserve(std::size_t(1) << 20);
    PopulateAhead off;  // off until enabled
    off.watch(w, big);
    CHECK(w.slot == -1);
    off.advance(w, big);  // a no-op, not a crash
}
