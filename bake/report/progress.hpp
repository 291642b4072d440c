// A progress bar with an ETA on stderr for one bake stage. Thread-safe: workers call
// advance(); at most one redraw every 0.2 s. Output only: it never changes a result.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace onelight::bake {

class Progress {
public:
    /// `enabled` false makes every call a no-op (tests, --quiet).
    Progress(std::string stage, uint64_t total, bool enabled);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void advance(uint64_t doneItems);
    /// Draws 100% and the stage's time, then a newline.
    void finish();
    double seconds() const;

private:
    void draw(uint64_t done, bool finalLine);
    std::string stage_;
    uint64_t total_;
    bool enabled_;
    bool finished_ = false;
    std::atomic<uint64_t> done_{0};
    std::mutex drawMutex_;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace onelight::bake
