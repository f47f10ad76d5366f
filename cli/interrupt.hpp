// An interrupted run (SIGINT: Ctrl-C; SIGTERM; SIGHUP) ends with whole rows and whole files: a signal
// that arrives while rows or a file are being written ends the process once that write is complete,
// any other at once, with exit status 128 + the signal's number (130 for SIGINT), as a shell reports a
// process the signal killed. Without the handlers (the default, e.g. run_cli in-process) nothing changes.
#pragma once

namespace ogive::cli {

// The program's handlers (main.cpp).
void install_interrupt_handlers();

// While one lives, an interrupting signal waits; when the last one ends, the process exits if one came.
class WholeWrite {
 public:
  WholeWrite();
  ~WholeWrite();
  WholeWrite(const WholeWrite&) = delete;
  WholeWrite& operator=(const WholeWrite&) = delete;
};

}  // namespace ogive::cli
