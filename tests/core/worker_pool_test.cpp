// WorkerPool (core/worker_pool.h): the threads parallel_chunks runs a frame's culling on.
#include "core/worker_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace bz {
namespace {

// The pool's runs: every task once, on distinct threads, the caller's among them; runs of
// different sizes one after another reuse its threads; a pool destroyed idle joins them.
TEST(WorkerPool, RunsEachTaskOnceOnItsOwnThreadAndKeepsItsThreads) {
    WorkerPool pool(4);
    EXPECT_EQ(pool.max_threads(), 4u);
    for (const std::size_t tasks : {1u, 4u, 2u, 3u, 4u, 1u, 9u}) {
        std::vector<std::atomic<int>> runs(4);
        std::vector<std::thread::id> ids(4);
        pool.run(tasks, [&](std::size_t i) {
            ++runs[i];
            ids[i] = std::this_thread::get_id();
        });
        const std::size_t ran = std::min<std::size_t>(tasks, 4);
        for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(runs[i].load(), i < ran ? 1 : 0) << tasks;
        EXPECT_EQ(ids[0], std::this_thread::get_id()) << "task 0 runs on the caller's thread";
        for (std::size_t i = 0; i < ran; ++i)
            for (std::size_t j = i + 1; j < ran; ++j) EXPECT_NE(ids[i], ids[j]) << tasks;
    }
    WorkerPool unused(8);  // never ran: starts no thread, and destroys cleanly
}

// Runs back to back from one thread while its threads may still be on their way back to
// sleep: no run is lost or taken twice.
TEST(WorkerPool, BackToBackRunsLoseNoTask) {
    WorkerPool pool(3);
    std::atomic<int> total{0};
    for (int round = 0; round < 2000; ++round)
        pool.run(1 + round % 3, [&](std::size_t) { ++total; });
    int expected = 0;
    for (int round = 0; round < 2000; ++round) expected += 1 + round % 3;
    EXPECT_EQ(total.load(), expected);
}

}  // namespace
}  // namespace bz
