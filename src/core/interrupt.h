#pragma once
// SIGINT and SIGTERM end every command promptly. By default a signal ends the process at once
// (exit status 128 + signal, after a one-line note on stderr): most commands have nothing to
// save, and nothing they do is left half-written (writes are atomic). A command that must
// save on the way out (play: the recording, changed settings) asks for a graceful stop
// instead: the signal then only raises a flag its loop polls, and a timer still ends the
// process if it has not finished within a grace period (stuck in a model import, say). A
// second signal always ends it at once.
//
// Signal handlers can only talk to the program through process-wide state, so this is the
// one place that keeps some (async-signal-safe atomics; see interrupt.cpp).
#include <chrono>

namespace bz {

// Installs the handlers (idempotent). Call first thing in main, before SDL starts: SDL only
// installs its own handlers (which turn the signals into quit events a blocked loop never
// reads) where none is installed.
void install_interrupt_handlers();

// From now on a signal asks for a stop rather than ending the process; the process still
// ends `grace` after the first signal if it has not exited by then.
void stop_gracefully_on_signal(std::chrono::milliseconds grace = std::chrono::seconds(5));

// True once SIGINT or SIGTERM arrived (graceful mode).
bool interrupt_requested();
// The signal that arrived (SIGINT, SIGTERM), or 0.
int interrupt_signal();
// The exit status for a command stopped by that signal: 128 + its number.
int interrupted_exit_code();

}  // namespace bz
