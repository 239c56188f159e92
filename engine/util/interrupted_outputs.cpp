#include "util/interrupted_outputs.h"

#include <signal.h>
#include <unistd.h>

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

void remove_all() {
  const int n = high_water.load(std::memory_order_acquire);
  for (int i = 0; i < n; ++i)  // files first
    if (char* p = table[static_cast<size_t>(i)].path.load(std::memory_order_acquire);
        p && !table[static_cast<size_t>(i)].directory.load(std::memory_order_acquire))
      unlink(p);
  for (int i = n - 1; i >= 0; --i)  // then folders, innermost (latest) first; rmdir keeps non-empty ones
    if (char* p = table[static_cast<size_t>(i)].path.load(std::memory_order_acquire);
        p && table[static_cast<size_t>(i)].directory.load(std::memory_order_acquire))
      rmdir(p);
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
