// A thread that faults in the pages just past the written end of growing
// arrays, so that the thread writing them (the interpreter filling its node
// arena, one 88-byte node at a time) no longer stops for a page fault every
// 46 nodes: on this project's virtual machines a fresh 4 KiB page costs
// ~1.5-2 us, ~10 ms of evaluating 10^5 translated spheres, while the second
// core idles (docs/performance.md, "Faulting the interpreter's arena ahead").
// It stays at most kAhead elements past what the writer reported (2.9 MB
// of nodes, 128 KB of 4-byte child ids), so an array reserved at a huge
// cap (address space only) is never populated whole, and what is faulted
// in but never written stays small.
//
// The thread must never act on a block its array has left. The writer
// stops it (stop(): joined, for good) before any push that would move a
// watched array; and the interpreter runs it only where a freed block goes
// back to the process's heap rather than to the system (cli/heap_policy.hpp:
// no block on a mapping of its own), so even a push outside that rule would
// at worst populate a free block of kerf's own heap, which changes no byte
// (or, on the heap's trimmed top, fail with ENOMEM).
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace kerf::csg {

class PopulateAhead {
public:
    static constexpr std::size_t kAhead = 32768;       // elements kept populated past an array's end
    static constexpr std::size_t kStep = kAhead / 8;  // the writer reports its end every kStep elements

    // The writer's side of one array: when to report next (in elements,
    // so the check per push is one compare) and where the array was.
    struct Watch {
        std::size_t next = SIZE_MAX;
        int slot = -1;
        const void* data = nullptr;
    };

    PopulateAhead() = default;
    PopulateAhead(const PopulateAhead&) = delete;
    PopulateAhead& operator=(const PopulateAhead&) = delete;
    ~PopulateAhead() { stop(); }

    // Starts keeping v's pages ahead of its end, up to its capacity (just
    // reserved: address space only). Starts the thread at the first call.
    template <class T>
    void watch(Watch& w, const std::vector<T>& v) {
        if (w.slot < 0) add(w, v.data(), v.size() * sizeof(T), v.capacity() * sizeof(T), sizeof(T));
    }
    // After a push: v's end moved (the report itself every kStep bytes).
    template <class T>
    void advance(Watch& w, const std::vector<T>& v) {
        if (v.size() >= w.next) report(w, v.data(), v.size() * sizeof(T), sizeof(T));
    }
    // Off until enabled, before the first watch(): only where a freed block
    // returns to the process's heap (see above), and not with --threads 1.
    void enable() { enabled_ = true; }
    // Stops and joins the thread, which no later watch() starts again (the
    // end of evaluation, its error, or a watched array about to move).
    void stop();
    // For the tests: whether the thread is running, and how many watched
    // arrays the writer found moved while it still ran (never, when every
    // move is preceded by stop()).
    bool running() const { return thread_.joinable(); }
    int moved_under_thread() const { return moved_under_thread_; }

private:
    static constexpr int kSlots = 8;
    struct Slot {
        char* base = nullptr;        // set before count_ publishes the slot, then fixed
        std::size_t cap = 0;
        std::size_t ahead = 0;       // kAhead elements, in bytes
        std::atomic<std::size_t> used{0};  // bytes the writer reported; SIZE_MAX: dropped
        std::size_t done = 0;        // the thread's own: populated up to here
    };
    void add(Watch& w, const void* data, std::size_t used, std::size_t cap, std::size_t elem);
    void report(Watch& w, const void* data, std::size_t used, std::size_t elem);
    void run();

    bool enabled_ = false;
    int moved_under_thread_ = 0;
    std::array<Slot, kSlots> slots_;
    std::atomic<int> count_{0};
    std::atomic<std::uint32_t> epoch_{0};  // bumped at each report: the thread waits on it
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace kerf::csg
