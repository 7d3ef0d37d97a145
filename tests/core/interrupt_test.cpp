// SIGINT / SIGTERM: by default the process ends at once with 128 + signal; in graceful mode
// the signal only raises a flag, and a timer ends a process that is stuck anyway.
#include "core/interrupt.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <thread>

namespace {

using namespace std::chrono_literals;

class InterruptSignals : public ::testing::Test {
  protected:
    void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

// The import child is forked (geometry/import/import_worker.cpp); a thread started before the
// fork could hold a lock the child then waits on forever.
TEST_F(InterruptSignals, InstallingTheHandlersStartsNoThread) {
    EXPECT_EXIT(
        {
            const auto threads = [] {
                int n = 0;
                for ([[maybe_unused]] const auto& t :
                     std::filesystem::directory_iterator("/proc/self/task")) {
                    ++n;
                }
                return n;
            };
            const int before = threads();
            bz::install_interrupt_handlers();
            bz::stop_gracefully_on_signal(10s);
            ::_exit(threads() == before ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST_F(InterruptSignals, DefaultModeEndsAtOnce) {
    EXPECT_EXIT(
        {
            bz::install_interrupt_handlers();
            std::raise(SIGINT);
            std::this_thread::sleep_for(10s);
            ::_exit(0);
        },
        ::testing::ExitedWithCode(130), "SIGINT: stopped");
}

TEST_F(InterruptSignals, GracefulModeRaisesTheFlag) {
    EXPECT_EXIT(
        {
            bz::install_interrupt_handlers();
            bz::stop_gracefully_on_signal(10s);
            std::raise(SIGTERM);
            ::_exit(bz::interrupt_requested() && bz::interrupt_signal() == SIGTERM
                        ? bz::interrupted_exit_code() - 100
                        : 1);
        },
        ::testing::ExitedWithCode(43), "");
}

TEST_F(InterruptSignals, StuckGracefulStopIsEndedByTheTimer) {
    EXPECT_EXIT(
        {
            bz::install_interrupt_handlers();
            bz::stop_gracefully_on_signal(200ms);
            std::raise(SIGTERM);
            std::this_thread::sleep_for(20s);  // a loop that never polls
            ::_exit(0);
        },
        ::testing::ExitedWithCode(143), "did not stop in time");
}

TEST_F(InterruptSignals, SecondSignalEndsAtOnce) {
    EXPECT_EXIT(
        {
            bz::install_interrupt_handlers();
            bz::stop_gracefully_on_signal(20s);
            std::raise(SIGTERM);
            std::raise(SIGINT);
            std::this_thread::sleep_for(10s);
            ::_exit(0);
        },
        ::testing::ExitedWithCode(130), "SIGINT: stopped");
}

}  // namespace
