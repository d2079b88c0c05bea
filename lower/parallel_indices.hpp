// for_each_index: a loop over [0, n) shared by a few threads, for lowering's
// wide unions (flat_tree.cpp: 10^5 translated spheres under one union are
// most of its time). Plain std::threads, not TBB's: the renderer sizes its
// TBB workers' stacks for the tree's depth (render/tracer/stack_depth.cpp)
// when it starts, which workers started earlier here would not get.
//
// Each index's work must touch only what is that index's own (its slots of
// preallocated arrays): the result is then the same bits whatever the
// thread count. Indices go out in chunks from a shared counter, so a thread
// the system deschedules mid-chunk holds the others up by one chunk at most.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <limits>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

#include "csg/huge_pages.hpp"
#include "csg/usable_cpus.hpp"

namespace kerf::lowering {

// `chunk`: how many indices a thread takes at a time. `threads`: how many
// threads may work (the caller's among them; 0, or more than the hardware
// has: one per hardware thread). When bodies throw, the exception of the
// lowest index is rethrown after all threads are done: the one a serial
// loop would have thrown, so the message never depends on the thread count.
template <class Body>
void for_each_index(std::size_t n, std::size_t chunk, unsigned threads, Body&& body) {
    const std::size_t kChunk = std::max<std::size_t>(chunk, 1);
    // No more than this process may run at once (--threads may ask for
    // 1,024; taskset may allow fewer CPUs than the machine has).
    const unsigned hardware = csg::usable_cpus();
    threads = threads == 0 ? hardware : std::min(threads, hardware);
    threads = unsigned(std::min<std::size_t>(threads, (n + kChunk - 1) / kChunk));
    std::atomic<std::size_t> next{0};
    std::mutex error_lock;  // taken only when a body throws
    std::size_t error_at = std::numeric_limits<std::size_t>::max();
    std::exception_ptr error;
    const auto work = [&] {
        for (;;) {
            const std::size_t begin = next.fetch_add(kChunk, std::memory_order_relaxed);
            if (begin >= n) return;
            const std::size_t end = std::min(n, begin + kChunk);
            for (std::size_t i = begin; i < end; ++i) {
                try {
                    body(i);
                } catch (...) {
                    const std::lock_guard<std::mutex> hold(error_lock);
                    if (i < error_at) {
                        error_at = i;
                        error = std::current_exception();
                    }
                    break;  // the rest of this chunk comes after i: never the lowest
                }
            }
        }
    };
    // Reserved first, so no push reallocates while helpers run; a helper
    // that cannot be had (no thread, no memory) leaves its share to the
    // others, and a started one is always joined.
    std::vector<std::thread> helpers;
    try {
        helpers.reserve(threads - 1);
    } catch (const std::bad_alloc&) {
        threads = 1;
    }
    for (unsigned t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(work);
        } catch (...) {
            break;
        }
    }
    work();
    for (std::thread& h : helpers) h.join();
    if (error) std::rethrow_exception(error);
}

// Has `threads` threads fault [data, data + bytes) in, 64 KiB at a time
// (csg::populate_pages): a big array's fresh pages, before one thread fills
// it, cost half the time.
inline void populate_in_parallel(void* data, std::size_t bytes, unsigned threads) {
    for_each_index(csg::populate_slices(bytes), 4, threads,
                   [&](std::size_t i) { csg::populate_slice(data, bytes, i); });
}

}  // namespace kerf::lowering
