#include "util/interrupted_outputs.h"

#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>

#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace penumbra::interrupted_outputs {

namespace {

// Entries are C strings owned by the table, published with release stores: the handler only
// reads pointers and calls unlink/rmdir, which are async-signal-safe.
struct Entry {
  std::atomic<char*> path{nullptr};
  std::atomic<bool> directory{false};
};
constexpr int kSlots = 16384;
std::array<Entry, kSlots> table;
std::atomic<int> high_water{0};  // slots in use are all below this

// One pass: files first, then folders, innermost (latest) first; rmdir keeps non-empty ones.
// True when no registered folder is left.
bool remove_pass() {
  const int n = high_water.load(std::memory_order_acquire);
  for (int i = 0; i < n; ++i)
    if (char* p = table[static_cast<size_t>(i)].path.load(std::memory_order_acquire);
        p && !table[static_cast<size_t>(i)].directory.load(std::memory_order_acquire))
      unlink(p);
  bool all_gone = true;
  for (int i = n - 1; i >= 0; --i)
    if (char* p = table[static_cast<size_t>(i)].path.load(std::memory_order_acquire);
        p && table[static_cast<size_t>(i)].directory.load(std::memory_order_acquire))
      if (rmdir(p) != 0 && errno != ENOENT) all_gone = false;
  return all_gone;
}

// A stop signal may be handled on any thread (the GL driver's own workers too), and the others
// run on meanwhile: the thread writing an output can create or rename a file between a pass's
// unlink and rmdir (`render --all-techniques` stopped in CI once left its folder behind). So a
// folder still there (not empty) gets more passes, 2 ms apart, for at most 50 ms; one holding
// files that are not ours stays.
void remove_all() {
  for (int pass = 0; pass < 25 && !remove_pass(); ++pass) {
    const timespec wait{0, 2000000};
    nanosleep(&wait, nullptr);
  }
}

extern "C" void on_stop_signal(int sig) {
  remove_all();
  signal(sig, SIG_DFL);
  raise(sig);
}

void install_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (sigaction(sig, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction handler {};
      handler.sa_handler = on_stop_signal;
      sigemptyset(&handler.sa_mask);
      sigaction(sig, &handler, nullptr);
    }
  });
}

int remember(const std::string& path, bool directory) {
  install_once();
  char* copy = static_cast<char*>(std::malloc(path.size() + 1));
  if (!copy) return -1;
  std::memcpy(copy, path.c_str(), path.size() + 1);
  for (int i = 0; i < kSlots; ++i) {
    char* expected = nullptr;
    Entry& e = table[static_cast<size_t>(i)];
    if (e.path.compare_exchange_strong(expected, copy, std::memory_order_acq_rel)) {
      // Until this store a handler may take a folder for a file or the reverse: unlink on a
      // folder and rmdir on a file both fail harmlessly.
      e.directory.store(directory, std::memory_order_release);
      int seen = high_water.load(std::memory_order_relaxed);
      while (seen < i + 1 && !high_water.compare_exchange_weak(seen, i + 1, std::memory_order_acq_rel)) {
      }
      return i;
    }
  }
  std::free(copy);
  return -1;
}

}  // namespace

int remember_file(const std::string& path) { return remember(path, false); }
int remember_directory(const std::string& path) { return remember(path, true); }

void forget(int handle) {
  if (handle < 0 || handle >= kSlots) return;
  // The string is not freed: a handler running now may still read it. A few bytes per output.
  table[static_cast<size_t>(handle)].path.store(nullptr, std::memory_order_release);
}

}  // namespace penumbra::interrupted_outputs
