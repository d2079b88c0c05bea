// A progress bar on standard error, drawn only when it is a terminal, so
// logs and editors that capture stderr see only diagnostics.
#pragma once
#include <chrono>
#include <mutex>

namespace kerf::cli {

class ProgressBar {
public:
    explicit ProgressBar(const char* label);
    ~ProgressBar();
    void update(double fraction);  // thread-safe; redraws at most ~10 times a second
    bool enabled() const { return enabled_; }

private:
    const char* label_;
    bool enabled_;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point start_, last_draw_;
    std::mutex mutex_;
};

}  // namespace kerf::cli
