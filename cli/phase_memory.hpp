// --stats: resident memory and elapsed time phase by phase (evaluate, lower,
// build, trace, write), so a memory or start-up cut can be measured where it
// happens (docs/performance.md, "Memory" and "Holes, the process around the
// render"). At the end of each phase it reads Linux's
// /proc/self/status: the run's peak so far (VmHWM) and what is resident now
// (VmRSS). The phase where the peak rises is the one that set it. The peak
// is never reset (/proc/self/clear_refs could), as that would also reset
// the figure `/usr/bin/time -v` reports for the whole run.
#pragma once
#include <mutex>
#include <string>
#include <vector>

namespace kerf::cli {

class PhaseMemory {
public:
    struct Mark {
        std::string phase;
        long peak_kb = 0, resident_kb = 0;  // at the end of the phase
        double ms = 0;  // wall time at its end since kerf's static initialisation (after the loader)
    };
    // Closes the current phase (its marks read) and opens `name`; a
    // repeated name is ignored. Thread-safe: the render's threads open "trace".
    void enter(const char* name);
    // Closes the current phase; then marks() is complete.
    void finish() { enter(nullptr); }
    // In run order; empty where /proc/self/status has no figures.
    const std::vector<Mark>& marks() const { return marks_; }

private:
    std::mutex mutex_;
    std::string current_;
    std::vector<Mark> marks_;
};

// "stats: memory (peak so far / resident, MB) at the end of: evaluate
// 335/330, lower 811/520, ..." (nothing when no phase was measured).
std::string phase_memory_line(const PhaseMemory& m);
// "stats: time (ms since start-up) at the end of: evaluate 2.1, lower 2.9,
// ...": the start is kerf's static initialisation, after the dynamic loader
// (nothing when no phase was measured).
std::string phase_time_line(const PhaseMemory& m);

}  // namespace kerf::cli
