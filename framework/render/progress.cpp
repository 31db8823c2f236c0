#include "render/progress.h"

#include <unistd.h>

#include <cstdio>

namespace rt {

bool stdout_is_terminal() {
    return isatty(STDOUT_FILENO) == 1;
}

ProgressBar::ProgressBar(long long total, bool enabled)
    : total_(total > 0 ? total : 1), enabled_(enabled) {
    start_ = last_draw_ = std::chrono::steady_clock::now();
}

ProgressBar::~ProgressBar() {
    if (!enabled_) return;
    draw(done_.load());
    std::printf("\n");
    std::fflush(stdout);
}

void ProgressBar::advance(long long amount) {
    const long long done = done_.fetch_add(amount) + amount;
    if (!enabled_) return;
    std::unique_lock lock(draw_mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;  // another thread is drawing; skip rather than wait
    const auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
    last_draw_ = now;
    draw(done);
}

void ProgressBar::draw(long long done) {
    const double fraction = double(done) / double(total_);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    constexpr int kWidth = 40;
    const int filled = int(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : ' ';
    bar[kWidth] = 0;
    std::printf("\r[%s] %3d%%  %5.1fs elapsed  ETA %5.1fs", bar, int(fraction * 100), elapsed, eta);
    std::fflush(stdout);
}

}  // namespace rt
