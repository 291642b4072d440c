#include "bake/report/progress.hpp"

#include <cstdio>

#include "bake/report/interrupt.hpp"

namespace onelight::bake {

Progress::Progress(std::string stage, uint64_t total, bool enabled)
    : stage_(std::move(stage)), total_(total), enabled_(enabled) {
    start_ = lastDraw_ = std::chrono::steady_clock::now();
    noteStage(stage_.c_str());
    if (enabled_) draw(0, false);
}

Progress::~Progress() {
    if (!finished_) finish();
}

double Progress::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::advance(uint64_t doneItems) {
    const uint64_t done = done_ += doneItems;
    if (!enabled_) return;
    std::unique_lock lock(drawMutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - lastDraw_).count() < 0.2) return;
    lastDraw_ = now;
    draw(done, false);
}

void Progress::finish() {
    finished_ = true;
    if (!enabled_) return;
    std::lock_guard lock(drawMutex_);
    draw(total_, true);
}

void Progress::draw(uint64_t done, bool finalLine) {
    constexpr int kWidth = 30;
    const double fraction = total_ > 0 ? std::min(1.0, double(done) / double(total_)) : 1.0;
    const int filled = static_cast<int>(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '-';
    bar[kWidth] = '\0';
    const double elapsed = seconds();
    if (finalLine) {
        std::fprintf(stderr, "\r%-10s [%s] 100%%  %.2f s            \n", stage_.c_str(), bar,
                     elapsed);
    } else if (fraction > 0.0) {
        const double eta = elapsed * (1.0 - fraction) / fraction;
        std::fprintf(stderr, "\r%-10s [%s] %3d%%  ETA %.1f s   ", stage_.c_str(), bar,
                     static_cast<int>(fraction * 100.0), eta);
    } else {
        std::fprintf(stderr, "\r%-10s [%s]   0%%  ETA --      ", stage_.c_str(), bar);
    }
    std::fflush(stderr);
}

}  // namespace onelight::bake
