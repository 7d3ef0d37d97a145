// SIGINT / SIGTERM: by default the process ends at once with 128 + signal; in graceful mode
// the signal only raises a flag, and a watchdog ends a process that is stuck anyway.
#include "core/interrupt.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <thread>

namespace {

using namespace std::chrono_literals;

class InterruptSignals : public ::testing::Test {
  protected:
    void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

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

TEST_F(InterruptSignals, StuckGracefulStopIsEndedByTheWatchdog) {
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
