#pragma once
// Runs `job(i, chunk)` for every i in [0, n) on up to `max_threads` of the pool's threads, in
// contiguous chunks of at least `min_per_chunk` jobs; chunk c's jobs come before chunk c+1's, so
// results gathered per chunk and concatenated in chunk order are the same as one thread's, whatever
// the thread count. Small work (n < 2 * min_per_chunk) runs on the calling thread. For CPU work
// a frame does before the GPU starts (culling thousands of clusters per instance).
#include <algorithm>
#include <cstddef>
#include <thread>

#include "core/worker_pool.h"

namespace bz {

// The chunk count parallel_chunks uses for n jobs.
inline std::size_t chunk_count(std::size_t n, std::size_t min_per_chunk, std::size_t max_threads) {
    if (n == 0) return 0;
    const std::size_t by_size =
        std::max<std::size_t>(1, n / std::max<std::size_t>(min_per_chunk, 1));
    return std::clamp<std::size_t>(std::min(by_size, max_threads), 1, n);
}

template <class Job>
void parallel_chunks(WorkerPool& pool, std::size_t n, std::size_t min_per_chunk,
                     std::size_t max_threads, const Job& job) {
    const std::size_t chunks =
        chunk_count(n, min_per_chunk, std::min(max_threads, pool.max_threads()));
    const auto run = [&](std::size_t c) {
        for (std::size_t i = n * c / chunks; i < n * (c + 1) / chunks; ++i) job(i, c);
    };
    if (chunks == 1) run(0);
    if (chunks > 1) pool.run(chunks, run);
}

// Processor threads worth using for such work (at least 1).
inline std::size_t worker_threads() {
    return std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
}

}  // namespace bz
