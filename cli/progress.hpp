// A progress line on standard error, drawn only when it is a terminal, so
// logs and editors that capture stderr see only diagnostics. It names the
// phase (evaluate, lower, build, trace, write) with the time spent in the
// run, and during trace a bar, the percentage and the time left.
#pragma once
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "cli/phase_memory.hpp"

namespace kerf::cli {

class ProgressBar {
public:
    // Drawn when `wanted` (not --no-progress) and stderr is a terminal.
    // `memory` (--stats), drawn or not: told of every phase change.
    explicit ProgressBar(bool wanted = true, PhaseMemory* memory = nullptr);
    ~ProgressBar();  // erases the line
    // Starts a phase. "build" is followed by "trace" at the first update().
    void phase(const char* name);
    // The finished fraction of the trace, from render threads (thread-safe).
    void update(double fraction);
    // Runs `print` (which writes lines to stderr) with the bar erased, so
    // diagnostics never land in the middle of it.
    void print_above(const std::function<void()>& print);
    bool enabled() const { return enabled_; }

private:
    // A thread of its own redraws the line ten times a second, so the time
    // moves during a long phase that reports no fraction (evaluate).
    void tick();

    bool enabled_;
    PhaseMemory* memory_;
    const char* phase_ = "";
    double fraction_ = -1;  // < 0: the phase has no fraction
    bool drawn_ = false, done_ = false;
    std::chrono::steady_clock::time_point start_, phase_start_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::thread ticker_;
};

// The line the bar draws (no terminal codes), for `elapsed` seconds into
// the run and `in_phase` into the phase; `fraction` < 0 when the phase has
// none. The time left is extrapolated from the phase's rate so far.
std::string progress_line(const char* phase, double fraction, double elapsed, double in_phase);

}  // namespace kerf::cli
