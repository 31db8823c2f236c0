// A one-line progress bar with an ETA, drawn only when stdout is a terminal.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace rt {

class ProgressBar {
  public:
    ProgressBar(long long total, bool enabled);
    ~ProgressBar();                      // finishes the line
    void advance(long long amount = 1);  // thread-safe

  private:
    void draw(long long done);

    long long total_;
    bool enabled_;
    std::atomic<long long> done_{0};
    std::mutex draw_mutex_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

// True when stdout is an interactive terminal.
bool stdout_is_terminal();

}  // namespace rt
