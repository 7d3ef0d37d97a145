#include "core/interrupt.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>
#include <ctime>

namespace bz {

namespace {

// Process-wide because a signal handler can reach nothing else. Only lock-free atomics,
// write() and timer_settime() are used from the handlers (all async-signal-safe).
std::atomic<int> g_signal{0};
std::atomic<bool> g_graceful{false};
std::atomic<long long> g_grace_ms{5000};
// Fires SIGALRM once the grace period after the first signal is over. A kernel timer, not a
// watchdog thread: the process stays single-threaded until SDL starts, so the import child
// forked by `check` and `render` (geometry/import/import_worker.cpp) never inherits a lock
// that another thread held at the fork.
timer_t g_grace_timer{};
std::atomic<bool> g_have_timer{false};

void write_note(int sig, const char* what) {
    const char* name = sig == SIGINT ? "SIGINT" : "SIGTERM";
    const char* parts[] = {"beamzone: ", name, what, "\n"};
    for (const char* p : parts) {
        const ssize_t n = ::write(STDERR_FILENO, p, std::strlen(p));
        (void)n;  // nothing more can be done about a failed note
    }
}

[[noreturn]] void end_now(int sig) {
    write_note(sig, ": stopped");
    ::_exit(128 + sig);
}

void start_grace_period() {
    const long long ms = std::max(g_grace_ms.load(), 1LL);
    itimerspec when{};
    when.it_value.tv_sec = static_cast<time_t>(ms / 1000);
    when.it_value.tv_nsec = static_cast<long>((ms % 1000) * 1000000);
    if (!g_have_timer.load() || ::timer_settime(g_grace_timer, 0, &when, nullptr) != 0) {
        // Without a timer there is nothing to end a stuck stop: end now rather than never.
        end_now(g_signal.load());
    }
}

void on_signal(int sig) {
    const int first = g_signal.exchange(sig);
    if (!g_graceful.load() || first != 0) end_now(sig);
    start_grace_period();
}

// The grace period is over and the process has not exited: it is stuck.
void on_grace_over(int) {
    const int sig = g_signal.load();
    write_note(sig, ": did not stop in time; ending now");
    ::_exit(128 + sig);
}

}  // namespace

void install_interrupt_handlers() {
    static const bool installed = [] {
        struct sigaction grace {};
        grace.sa_handler = on_grace_over;
        sigemptyset(&grace.sa_mask);
        sigaction(SIGALRM, &grace, nullptr);
        sigevent ev{};
        ev.sigev_notify = SIGEV_SIGNAL;
        ev.sigev_signo = SIGALRM;
        g_have_timer.store(::timer_create(CLOCK_MONOTONIC, &ev, &g_grace_timer) == 0);
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        sigaction(SIGINT, &sa, nullptr);
        sigaction(SIGTERM, &sa, nullptr);
        return true;
    }();
    (void)installed;
}

void stop_gracefully_on_signal(std::chrono::milliseconds grace) {
    g_grace_ms.store(grace.count());
    g_graceful.store(true);
}

bool interrupt_requested() {
    return g_signal.load() != 0;
}

int interrupt_signal() {
    return g_signal.load();
}

int interrupted_exit_code() {
    const int sig = g_signal.load();
    return sig ? 128 + sig : 0;
}

}  // namespace bz
