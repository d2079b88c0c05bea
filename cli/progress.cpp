#include "cli/progress.hpp"

#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace kerf::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

std::string progress_line(const char* phase, double fraction, double elapsed, double in_phase) {
    char buf[160];
    if (fraction < 0) {
        std::snprintf(buf, sizeof buf, "%-8s %.1fs", phase, elapsed);
        return buf;
    }
    constexpr int width = 30;
    const int percent = static_cast<int>(fraction * 100.0);
    const int filled = percent * width / 100;
    // Too early for a meaningful rate: no guess.
    char eta[32] = "ETA --";
    if (fraction >= 0.02 && in_phase > 0.05) std::snprintf(eta, sizeof eta, "ETA %.1fs", in_phase * (1 - fraction) / fraction);
    std::snprintf(buf, sizeof buf, "%-8s [%.*s%*s] %3d%% %.1fs %s", phase, filled, "##############################",
                  width - filled, "", percent, elapsed, eta);
    return buf;
}

ProgressBar::ProgressBar(bool wanted, PhaseMemory* memory)
    : enabled_(wanted && isatty(STDERR_FILENO) != 0), memory_(memory), start_(Clock::now()), phase_start_(start_) {
    if (enabled_) ticker_ = std::thread([this] { tick(); });
}

ProgressBar::~ProgressBar() {
    if (!enabled_) return;
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    ticker_.join();
    if (drawn_) std::fputs("\r\033[K", stderr);
}

void ProgressBar::phase(const char* name) {
    if (memory_) memory_->enter(name);
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    phase_ = name;
    fraction_ = -1;
    phase_start_ = Clock::now();
}

void ProgressBar::update(double fraction) {
    if (memory_) memory_->enter("trace");  // once per phase: a repeated name is ignored
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    if (std::strcmp(phase_, "trace") != 0) {  // the BVHs are built: tracing starts
        phase_ = "trace";
        phase_start_ = Clock::now();
    }
    fraction_ = fraction;
}

void ProgressBar::print_above(const std::function<void()>& print) {
    std::lock_guard lock(mutex_);
    if (drawn_) std::fputs("\r\033[K", stderr);
    print();
}

void ProgressBar::tick() {
    std::unique_lock lock(mutex_);
    // A render shorter than this shows no line at all: no flicker in `kerf
    // watch` for scenes that take a tenth of a second.
    if (wake_.wait_for(lock, std::chrono::milliseconds(150), [this] { return done_; })) return;
    do {
        const auto now = Clock::now();
        const std::string line = progress_line(phase_, fraction_, seconds(now - start_), seconds(now - phase_start_));
        std::fprintf(stderr, "\r\033[K%s", line.c_str());
        std::fflush(stderr);
        drawn_ = true;
    } while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return done_; }));
}

}  // namespace kerf::cli
