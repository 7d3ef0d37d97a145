#include "core/interrupt.h"

#include <semaphore.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <thread>

namespace bz {

namespace {

// Process-wide because a signal handler can reach nothing else. Only lock-free atomics and
// sem_post are touched from the handler (both async-signal-safe).
std::atomic<int> g_signal{0};
std::atomic<bool> g_graceful{false};
std::atomic<long long> g_grace_ms{5000};
sem_t g_wake;  // posted by the handler; the watchdog thread waits on it

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

void on_signal(int sig) {
    const int first = g_signal.exchange(sig);
    if (!g_graceful.load() || first != 0) end_now(sig);
    ::sem_post(&g_wake);
}

// Ends the process if a graceful stop takes longer than the grace period.
void watchdog() {
    while (::sem_wait(&g_wake) != 0) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(g_grace_ms.load()));
    const int sig = g_signal.load();
    write_note(sig, ": did not stop in time; ending now");
    ::_exit(128 + sig);
}

}  // namespace

void install_interrupt_handlers() {
    static const bool installed = [] {
        ::sem_init(&g_wake, 0, 0);
        std::thread(watchdog).detach();
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
