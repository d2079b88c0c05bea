#include "cli/phase_memory.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace kerf::cli {

namespace {
// Set during static initialisation, before main: the origin of the marks' times.
const std::chrono::steady_clock::time_point g_start = std::chrono::steady_clock::now();
}  // namespace

void PhaseMemory::enter(const char* name) {
    std::lock_guard lock(mutex_);
    if (name && current_ == name) return;
    if (!current_.empty()) {
        Mark m{current_, -1, -1,
               std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - g_start).count()};
        std::ifstream status("/proc/self/status");
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("VmHWM:", 0) == 0) m.peak_kb = std::strtol(line.c_str() + 6, nullptr, 10);
            if (line.rfind("VmRSS:", 0) == 0) m.resident_kb = std::strtol(line.c_str() + 6, nullptr, 10);
        }
        // The kernel's counters are per-thread caches summed lazily, so two
        // reads can see VmHWM step back a little or VmRSS above it; "peak so
        // far" is the running maximum of both.
        if (!marks_.empty()) m.peak_kb = std::max(m.peak_kb, marks_.back().peak_kb);
        m.peak_kb = std::max(m.peak_kb, m.resident_kb);
        if (m.peak_kb >= 0 && m.resident_kb >= 0) marks_.push_back(std::move(m));
    }
    current_ = name ? name : "";
}

namespace {

// "HEAD phase FIGURES, phase FIGURES, ...\n", each mark's figures printed
// by `figures` into buf (nothing when no phase was measured).
template <class Figures>
std::string marks_line(const PhaseMemory& m, const char* head, Figures figures) {
    if (m.marks().empty()) return {};
    std::string line = head;
    char buf[96];
    for (std::size_t i = 0; i < m.marks().size(); ++i) {
        line += i ? ", " : " ";
        line += m.marks()[i].phase;
        figures(buf, sizeof buf, m.marks()[i]);
        line += buf;
    }
    return line + "\n";
}

}  // namespace

std::string phase_memory_line(const PhaseMemory& m) {
    return marks_line(m, "stats: memory (peak so far / resident, MB) at the end of:",
                      [](char* buf, std::size_t n, const PhaseMemory::Mark& k) {
                          std::snprintf(buf, n, " %.0f/%.0f", k.peak_kb / 1024.0, k.resident_kb / 1024.0);
                      });
}

std::string phase_time_line(const PhaseMemory& m) {
    return marks_line(m, "stats: time (ms since start-up) at the end of:",
                      [](char* buf, std::size_t n, const PhaseMemory::Mark& k) { std::snprintf(buf, n, " %.1f", k.ms); });
}

}  // namespace kerf::cli
