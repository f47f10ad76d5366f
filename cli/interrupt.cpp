#include "interrupt.hpp"

#include <atomic>
#include <csignal>

#include <unistd.h>

namespace ogive::cli {
namespace {

// A handler may touch only lock-free atomics and async-signal-safe calls (_exit).
std::atomic<int> writes{0};   // WholeWrites alive
std::atomic<int> arrived{0};  // the signal that came, 0 for none
static_assert(std::atomic<int>::is_always_lock_free);

// Sequentially consistent on both sides: either the handler sees the write in progress and leaves the
// exit to ~WholeWrite, or ~WholeWrite sees the signal, or both (the exit happens once: _exit ends it).
void on_signal(int signal) {
  arrived.store(signal);
  if (writes.load() == 0) ::_exit(128 + signal);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write the signal interrupts goes on
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal ignored by whoever started the program (nohup, a shell's background job) stays ignored.
    struct sigaction before {};
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

WholeWrite::WholeWrite() { writes.fetch_add(1); }

WholeWrite::~WholeWrite() {
  if (writes.fetch_sub(1) == 1)
    if (const int signal = arrived.load(); signal != 0) ::_exit(128 + signal);
}

}  // namespace ogive::cli
