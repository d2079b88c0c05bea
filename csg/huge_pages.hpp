// Lowering a million leaves writes ~0.5 GB of fresh memory. Transparent
// huge pages on the big arrays (a hint, ignored where unsupported) cut the
// number of page faults by 512x, but on virtual machines that hand free
// 2 MiB blocks back to the host each huge page's first touch waits for the
// host: the hint is given only with KERF_HUGE_PAGES=1 (huge_pages.cpp).
#pragma once
#include <cstddef>
#include <iterator>
#include <vector>

namespace kerf::csg {

constexpr std::size_t kHugePage = std::size_t(2) << 20;  // x86-64 transparent huge page

// Advises huge pages over the whole 2 MiB pages inside [data, data + bytes)
// where KERF_HUGE_PAGES=1; blocks under two huge pages are left alone.
void advise_huge_pages(void* data, std::size_t bytes);

// Has the kernel back [data, data + bytes) with written pages now
// (MADV_POPULATE_WRITE, Linux 5.14; elsewhere nothing): one call instead
// of a fault per 4 KiB page, callable from several threads on parts of one
// block so that a big array's first touch is shared among them (on this
// project's virtual machines a fresh page costs ~1.5-2 us). Contents are
// kept: pages already there are left as they are. A hint: failure is fine;
// false when the kernel does not know the advice (EINVAL: before 5.14).
bool populate_pages(void* data, std::size_t bytes);

// A big array is populated by several threads a slice at a time: slice i
// of [data, data + bytes), for i < populate_slices(bytes). 64 KiB: 16
// pages, a share small enough that a descheduled thread delays little.
constexpr std::size_t kPopulateSlice = std::size_t(64) << 10;
constexpr std::size_t populate_slices(std::size_t bytes) { return (bytes + kPopulateSlice - 1) / kPopulateSlice; }
inline void populate_slice(void* data, std::size_t bytes, std::size_t i) {
    const std::size_t from = i * kPopulateSlice;
    populate_pages(static_cast<char*>(data) + from, bytes - from < kPopulateSlice ? bytes - from : kPopulateSlice);
}

// Reserves `count` elements and advises huge pages over the whole buffer,
// before the elements already there move in (so their copy lands on huge
// pages too, not on 4 KiB faults).
template <typename T>
void reserve_huge(std::vector<T>& v, std::size_t count) {
    if (count <= v.capacity()) return;
    std::vector<T> fresh;
    fresh.reserve(count);
    advise_huge_pages(fresh.data(), fresh.capacity() * sizeof(T));
    fresh.insert(fresh.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.swap(fresh);
}

}  // namespace kerf::csg
