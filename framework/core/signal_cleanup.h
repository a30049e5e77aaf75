// What SIGINT, SIGTERM and SIGHUP must undo before the process ends: the temporary files being
// written and the child processes (TetGen) running for it. The one piece of process-wide state
// of voroseal: a signal handler cannot reach anything else.
//
// The registry is a fixed table of slots written with atomics, so that the handler, which may
// run in the middle of a registration, only ever sees complete entries; the handler uses
// async-signal-safe calls only (unlink, kill, _exit). Registration is cheap and safe whether
// or not the handlers are installed (the library and the Python module never install them).
#pragma once

#include <sys/types.h>

namespace voroseal {

/// Installs the handlers (the CLI does, once): on SIGINT, SIGTERM or SIGHUP the registered
/// temporary files are removed, the registered process groups are killed (SIGKILL), and the
/// process exits with 128 + the signal number (130, 143, 129). A signal that was ignored when
/// the program started (nohup) stays ignored.
void install_signal_cleanup();

/// Registers a file to remove on a signal; returns its slot, or -1 when the table is full or
/// the path too long (the file is then simply not removed on a signal).
int register_temp_file(const char* path);
/// Forgets a slot of register_temp_file() (after the file was renamed or removed); -1 is a no-op.
void unregister_temp_file(int slot);

/// Registers a process group to kill on a signal; returns its slot or -1.
int register_child_group(pid_t group);
void unregister_child_group(int slot);

/// Blocks the cleanup signals while alive, so that a file is never created without being
/// registered (or renamed without being unregistered): a signal arriving meanwhile is handled
/// when the scope ends.
class SignalBlock {
 public:
  SignalBlock();
  ~SignalBlock();
  SignalBlock(const SignalBlock&) = delete;
  SignalBlock& operator=(const SignalBlock&) = delete;

 private:
  // The previous sigset_t, opaque here to keep <signal.h> out of the header.
  alignas(alignof(long)) unsigned char saved_[128];
};

}  // namespace voroseal
