#include "cli/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace kerf::cli {

ProgressBar::ProgressBar(const char* label)
    : label_(label), enabled_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (enabled_ && last_percent_ >= 0) std::fputs("\r\033[K", stderr);
}

void ProgressBar::update(double fraction) {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    auto now = std::chrono::steady_clock::now();
    int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_ || (percent < 100 && now - last_draw_ < std::chrono::milliseconds(100)))
        return;
    last_percent_ = percent;
    last_draw_ = now;
    constexpr int width = 30;
    int filled = percent * width / 100;
    double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%% %.1fs", label_, filled,
                 "##############################", width - filled, "", percent, elapsed);
    std::fflush(stderr);
}

}  // namespace kerf::cli
