#include "framework/core/signal_cleanup.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstring>

namespace voroseal {

namespace {

// Slots: enough for every file a command writes at once (TetGen output: three) and its child.
constexpr int kTempSlots = 16;
constexpr int kChildSlots = 4;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// A slot's state: free, being written (the handler skips it), ready.
enum SlotState : int { kFree = 0, kWriting = 1, kReady = 2 };

struct TempSlot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};

// The registry, process-wide because a signal handler can reach nothing else.
TempSlot g_temps[kTempSlots];
std::atomic<pid_t> g_children[kChildSlots];
// The process that installed the handlers: a forked child inherits them and must not remove
// its parent's files.
std::atomic<pid_t> g_owner{0};

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

extern "C" void on_cleanup_signal(int sig) {
  if (::getpid() == g_owner.load()) {
    for (std::atomic<pid_t>& child : g_children) {
      const pid_t group = child.load();
      if (group > 0) ::kill(-group, SIGKILL);
    }
    for (TempSlot& slot : g_temps)
      if (slot.state.load() == kReady) ::unlink(slot.path);
  }
  ::_exit(128 + sig);
}

}  // namespace

void install_signal_cleanup() {
  g_owner.store(::getpid());
  for (int sig : kSignals) {
    struct sigaction previous;
    if (::sigaction(sig, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = on_cleanup_signal;
    sigfillset(&action.sa_mask);  // one cleanup at a time
    ::sigaction(sig, &action, nullptr);
  }
}

int register_temp_file(const char* path) {
  const size_t n = std::strlen(path);
  if (n >= PATH_MAX) return -1;
  for (int i = 0; i < kTempSlots; ++i) {
    int expected = kFree;
    if (!g_temps[i].state.compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(g_temps[i].path, path, n + 1);
    g_temps[i].state.store(kReady);
    return i;
  }
  return -1;
}

void unregister_temp_file(int slot) {
  if (slot >= 0 && slot < kTempSlots) g_temps[slot].state.store(kFree);
}

int register_child_group(pid_t group) {
  for (int i = 0; i < kChildSlots; ++i) {
    pid_t expected = 0;
    if (g_children[i].compare_exchange_strong(expected, group)) return i;
  }
  return -1;
}

void unregister_child_group(int slot) {
  if (slot >= 0 && slot < kChildSlots) g_children[slot].store(0);
}

SignalBlock::SignalBlock() {
  static_assert(sizeof(sigset_t) <= sizeof(saved_), "SignalBlock::saved_ is too small");
  sigset_t block;
  sigemptyset(&block);
  for (int sig : kSignals) sigaddset(&block, sig);
  ::pthread_sigmask(SIG_BLOCK, &block, reinterpret_cast<sigset_t*>(saved_));
}

SignalBlock::~SignalBlock() {
  ::pthread_sigmask(SIG_SETMASK, reinterpret_cast<sigset_t*>(saved_), nullptr);
}

}  // namespace voroseal
