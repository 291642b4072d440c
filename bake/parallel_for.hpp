// The baker's one parallel loop: tbb::parallel_for, plus, under ThreadSanitizer, the fork and
// join edges TSan cannot see inside Debian's uninstrumented TBB (each body starts after what the
// caller wrote before the loop; the caller's code after the loop sees everything the bodies
// wrote). Races between bodies, the ones that matter, stay visible.
#pragma once

#include <tbb/parallel_for.h>

#if defined(__SANITIZE_THREAD__)
#define ONELIGHT_TSAN_ANNOTATE 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ONELIGHT_TSAN_ANNOTATE 1
#endif
#endif

#ifdef ONELIGHT_TSAN_ANNOTATE
#include <sanitizer/tsan_interface.h>
#endif

namespace onelight::bake {

namespace detail {

// Marks the loop's fork (release by the caller, acquire by each body) and join (release by
// each body, acquire by the caller); no-ops without TSan.
struct LoopEdges {
    char fork = 0, join = 0;
    void beforeLoop() {
#ifdef ONELIGHT_TSAN_ANNOTATE
        __tsan_release(&fork);
#endif
    }
    void bodyStarts() {
#ifdef ONELIGHT_TSAN_ANNOTATE
        __tsan_acquire(&fork);
#endif
    }
    void bodyEnds() {
#ifdef ONELIGHT_TSAN_ANNOTATE
        __tsan_release(&join);
#endif
    }
    void afterLoop() {
#ifdef ONELIGHT_TSAN_ANNOTATE
        __tsan_acquire(&join);
#endif
    }
};

}  // namespace detail

/// tbb::parallel_for(range, body).
template <typename Range, typename Body>
void parallelFor(const Range& range, const Body& body) {
    detail::LoopEdges edges;
    edges.beforeLoop();
    tbb::parallel_for(range, [&](const Range& part) {
        edges.bodyStarts();
        body(part);
        edges.bodyEnds();
    });
    edges.afterLoop();
}

/// tbb::parallel_for(first, last, body): body(i) for i in [first, last).
template <typename Index, typename Body>
void parallelFor(Index first, Index last, const Body& body) {
    detail::LoopEdges edges;
    edges.beforeLoop();
    tbb::parallel_for(first, last, [&](Index i) {
        edges.bodyStarts();
        body(i);
        edges.bodyEnds();
    });
    edges.afterLoop();
}

}  // namespace onelight::bake
