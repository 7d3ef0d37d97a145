// The import process: whatever the importer does with a hostile file (runs forever, eats
// memory, crashes) stays in the child and comes back as one line naming the file; a good
// result comes back intact.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>
#include <vector>

#include "core/error.h"
#include "geometry/import/import_worker.h"

namespace bz::geo::detail {
namespace {

using Clock = std::chrono::steady_clock;

std::string error_of(const ImportLimits& limits, const std::function<TriMesh()>& work) {
    try {
        run_isolated("model.obj", limits, work);
    } catch (const UserError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no UserError";
    return {};
}

TEST(ImportIsolation, MeshComesBackIntact) {
    TriMesh big;
    for (std::uint32_t i = 0; i < 300000; ++i) {
        big.positions.emplace_back(static_cast<float>(i), 0.5f * static_cast<float>(i), -1.0f);
        big.indices.push_back(i);
    }
    const TriMesh back = run_isolated("big.obj", ImportLimits{}, [&big] { return big; });
    EXPECT_EQ(back.positions, big.positions);
    EXPECT_EQ(back.indices, big.indices);
}

TEST(ImportIsolation, UserErrorOfTheChildIsPassedOnUnchanged) {
    const std::string m = error_of(ImportLimits{}, []() -> TriMesh {
        throw UserError("model.obj: error: something precise");
    });
    EXPECT_EQ(m, "model.obj: error: something precise");
}

TEST(ImportIsolation, BlockedImportIsAbandonedAtTheWallClockDeadline) {
    ImportLimits limits;
    limits.wall_seconds = 0.3;
    const auto start = Clock::now();
    const std::string m = error_of(limits, []() -> TriMesh {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    });
    const double took = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_NE(m.find("model.obj: error: import did not finish within 0.3 s"), std::string::npos)
        << m;
    EXPECT_LT(took, 5.0);
}

TEST(ImportIsolation, SpinningImportIsAbandonedAfterItsCpuTime) {
    ImportLimits limits;
    limits.seconds = 0.3;
    const auto start = Clock::now();
    const std::string m = error_of(limits, []() -> TriMesh {
        volatile unsigned long long spin = 0;
        for (;;) spin = spin + 1;
    });
    const double took = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_NE(m.find("model.obj: error: import took more than 0.3 s of CPU time and was abandoned"),
              std::string::npos)
        << m;
    EXPECT_LT(took, 30.0);
}

// Time the import spends without the CPU (a busy machine, a slow disk) does not count against
// its CPU limit: a model that imports in milliseconds is not refused because of the load.
TEST(ImportIsolation, WaitingIsNotCountedAsImportTime) {
    ImportLimits limits;
    limits.seconds = 0.2;
    const TriMesh back = run_isolated("m.obj", limits, [] {
        std::this_thread::sleep_for(std::chrono::milliseconds(600));
        TriMesh t;
        t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        t.indices = {0, 1, 2};
        return t;
    });
    EXPECT_EQ(back.indices.size(), 3u);
}

TEST(ImportIsolation, MemoryHungryImportHitsTheCap) {
    ImportLimits limits;
    limits.memory_bytes = std::uint64_t{200} << 20;
    const std::string m = error_of(limits, []() -> TriMesh {
        // Touch every page, as a loader filling a buffer it was told to allocate would.
        std::vector<std::vector<char>> blocks;
        for (int i = 0; i < 64; ++i) blocks.emplace_back(std::size_t{32} << 20, 'x');
        return {};
    });
    EXPECT_NE(m.find("model.obj: error: import needed more than 200 MB of memory"),
              std::string::npos)
        << m;
}

TEST(ImportIsolation, CrashingImporterBecomesAMessage) {
    const std::string m = error_of(ImportLimits{}, []() -> TriMesh {
        std::raise(SIGABRT);
        return {};
    });
    EXPECT_NE(m.find("model.obj: error: the importer crashed on this file (SIGABRT"),
              std::string::npos)
        << m;
    EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(ImportIsolation, ParentStateIsUntouchedByTheChild) {
    int counter = 1;
    run_isolated("m.obj", ImportLimits{}, [&counter] {
        counter = 99;  // the child's copy
        TriMesh t;
        t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        t.indices = {0, 1, 2};
        return t;
    });
    EXPECT_EQ(counter, 1);
}

}  // namespace
}  // namespace bz::geo::detail
