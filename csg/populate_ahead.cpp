#include "csg/populate_ahead.hpp"

#include <algorithm>
#include <system_error>

#include "csg/huge_pages.hpp"

namespace kerf::csg {

namespace {
constexpr std::size_t kSlice = std::size_t(256) << 10;  // one madvise: stop() waits at most one
}  // namespace

void PopulateAhead::add(Watch& w, const void* data, std::size_t used, std::size_t cap, std::size_t elem) {
    const int i = count_.load(std::memory_order_relaxed);
    if (!enabled_ || i == kSlots || cap < used + 2 * kStep * elem) return;
    Slot& s = slots_[i];
    s.base = static_cast<char*>(const_cast<void*>(data));
    s.cap = cap;
    s.ahead = kAhead * elem;
    s.used.store(used, std::memory_order_relaxed);
    s.done = used;
    count_.store(i + 1, std::memory_order_release);
    w.slot = i;
    w.data = data;
    w.next = used / elem + kStep;
    if (!thread_.joinable()) {
        try {
            thread_ = std::thread([this] { run(); });
        } catch (const std::system_error&) {  // no thread: the writer faults its pages as before
            enabled_ = false;
            count_.store(0, std::memory_order_release);
            w = Watch{};
            return;
        }
    }
    epoch_.fetch_add(1, std::memory_order_release);
    epoch_.notify_one();
}

void PopulateAhead::report(Watch& w, const void* data, std::size_t used, std::size_t elem) {
    Slot& s = slots_[static_cast<std::size_t>(w.slot)];
    if (data != w.data) {  // grew past its cap and moved: the old block is not ours any more
        if (thread_.joinable()) ++moved_under_thread_;  // the writer should have stopped the thread first
        s.used.store(SIZE_MAX, std::memory_order_relaxed);
        w.next = SIZE_MAX;
        return;
    }
    w.next = used / elem + kStep;
    s.used.store(used, std::memory_order_relaxed);
    epoch_.fetch_add(1, std::memory_order_release);
    epoch_.notify_one();
}

void PopulateAhead::stop() {
    enabled_ = false;
    if (!thread_.joinable()) return;
    stop_.store(true, std::memory_order_relaxed);
    epoch_.fetch_add(1, std::memory_order_release);
    epoch_.notify_one();
    thread_.join();
}

void PopulateAhead::run() {
    for (;;) {
        const std::uint32_t seen = epoch_.load(std::memory_order_acquire);
        // Read after `seen`: a stop() whose bump `seen` already holds is
        // seen here (its release, this acquire), so the wait below cannot
        // sleep through it (read before, its notify could come and go
        // between the two loads and the wait would never end).
        if (stop_.load(std::memory_order_relaxed)) return;
        bool worked = false;
        const int n = count_.load(std::memory_order_acquire);
        for (int i = 0; i < n && !stop_.load(std::memory_order_relaxed); ++i) {
            Slot& s = slots_[static_cast<std::size_t>(i)];
            const std::size_t used = s.used.load(std::memory_order_relaxed);
            if (used == SIZE_MAX) continue;
            s.done = std::max(s.done, used);  // the writer got there first: its pages are in
            const std::size_t target = std::min(s.cap, used + s.ahead);
            if (s.done >= target) continue;
            const std::size_t len = std::min(kSlice, target - s.done);
            if (!populate_pages(s.base + s.done, len)) return;  // a kernel without MADV_POPULATE_WRITE
            s.done += len;
            worked = true;
        }
        if (!worked) epoch_.wait(seen, std::memory_order_acquire);
    }
}

}  // namespace kerf::csg
