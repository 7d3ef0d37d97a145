// parallel_chunks (core/parallel_chunks.h) on a WorkerPool (core/worker_pool.h): every job runs
// once, chunks keep job order, and results gathered per chunk equal one thread's at any thread
// count.
#include "core/parallel_chunks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <vector>

namespace bz {
namespace {

std::vector<std::size_t> gathered(WorkerPool& pool, std::size_t n, std::size_t threads) {
    const std::size_t chunks = chunk_count(n, 1, std::min(threads, pool.max_threads()));
    std::vector<std::vector<std::size_t>> per_chunk(chunks);
    parallel_chunks(pool, n, 1, threads, [&](std::size_t i, std::size_t c) {
        // Jobs give different amounts of output, as instances do.
        for (std::size_t k = 0; k < i % 3; ++k) per_chunk[c].push_back(i * 10 + k);
    });
    std::vector<std::size_t> out;
    for (const auto& v : per_chunk) out.insert(out.end(), v.begin(), v.end());
    return out;
}

TEST(ParallelChunks, GatheredResultsAreTheSameAtAnyThreadCount) {
    // One pool for every run, as a renderer keeps one, and a small one that caps them.
    WorkerPool pool(8), small(2);
    for (const std::size_t n : {0u, 1u, 2u, 7u, 40u, 1000u}) {
        const std::vector<std::size_t> one = gathered(pool, n, 1);
        for (const std::size_t threads : {2u, 3u, 8u, 64u}) {
            EXPECT_EQ(gathered(pool, n, threads), one) << n << " jobs, " << threads << " threads";
            EXPECT_EQ(gathered(small, n, threads), one) << n << " jobs, two threads at most";
        }
    }
}

TEST(ParallelChunks, EveryJobRunsExactlyOnce) {
    WorkerPool pool(8);
    for (int round = 0; round < 50; ++round) {
        std::vector<std::atomic<int>> runs(997);
        parallel_chunks(pool, runs.size(), 10, 8, [&](std::size_t i, std::size_t) { ++runs[i]; });
        for (const auto& r : runs) ASSERT_EQ(r.load(), 1) << "round " << round;
    }
}

TEST(ParallelChunks, SmallWorkStaysOnOneChunk) {
    EXPECT_EQ(chunk_count(0, 1, 8), 0u);
    EXPECT_EQ(chunk_count(5, 10, 8), 1u);
    EXPECT_EQ(chunk_count(100, 10, 8), 8u);
    EXPECT_EQ(chunk_count(3, 1, 8), 3u);
}

}  // namespace
}  // namespace bz
