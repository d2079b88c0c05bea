// parallel_for_build: the tracer's per-leaf, per-node and per-unit tables of a
// big scene filled by the threads of the TBB arena it is built in (the
// render's: --threads, their stacks sized for the tree, stack_depth.cpp).
// Each index writes only its own slots, so the tables are the same bits
// whatever the thread count; a small scene's loops stay plain, where waking
// the workers would cost more than they save.
#pragma once
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "csg/huge_pages.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

namespace kerf::render {

constexpr std::size_t kParallelBuild = 32768;  // fewer: one thread (at 10^4 units two cost 0.2 ms more than one)

template <class Body>
void parallel_for_build(std::size_t n, Body&& body) {
    if (n < kParallelBuild) {
        for (std::size_t i = 0; i < n; ++i) body(i);
        return;
    }
    // Chunks of 2048: a worker descheduled mid-chunk holds the build up by
    // ~0.1 ms at most.
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 2048),
        [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
        },
        tbb::simple_partitioner());
}

// Reserves `n` elements of a fresh table and, when it is big, has the
// arena's threads fault its pages in (csg::populate_pages) before one
// thread's resize or assign writes it: fresh pages are most of what such a
// table costs on this project's virtual machines (~1.5-2 us each).
template <class T>
void reserve_populated(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    const std::size_t bytes = n * sizeof(T);
    if (bytes < 16 * csg::kPopulateSlice) return;
    void* const p = v.data();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, csg::populate_slices(bytes), 4),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) csg::populate_slice(p, bytes, i);
                      },
                      tbb::simple_partitioner());
}

// One step of a big build run by a thread of the arena alongside what the
// constructing thread does next: the step and the constructing thread
// share only what neither writes until join(). A small build's, or with
// `concurrent` false, runs at once.
// join() waits and rethrows its exception; the destructor (an exception
// unwinding the build) waits too, and drops it.
class ConcurrentStep {
public:
    template <class F>
    ConcurrentStep(bool concurrent, F&& step) {
        if (!concurrent) {
            step();
            return;
        }
        group_.run(std::forward<F>(step));
        running_ = true;
    }
    ConcurrentStep(const ConcurrentStep&) = delete;
    ConcurrentStep& operator=(const ConcurrentStep&) = delete;
    void join() {
        if (!running_) return;
        running_ = false;
        group_.wait();
    }
    ~ConcurrentStep() {
        if (!running_) return;
        try {
            group_.wait();
        } catch (...) {  // the build is failing already: its own exception goes on
        }
    }

private:
    tbb::task_group group_;
    bool running_ = false;
};

}  // namespace kerf::render
