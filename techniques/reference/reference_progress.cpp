#include "reference_progress.h"

#include <mutex>

namespace penumbra::reference {
namespace {
std::mutex g_mutex;
ReferenceProgress g_progress;
}  // namespace

ReferenceProgress reference_progress() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return g_progress;
}

void publish_reference_progress(const std::string& method, std::int64_t done, std::int64_t total) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_progress.method = method;
  g_progress.done = done;
  g_progress.total = total;
}

void count_reference_reset() {
  std::lock_guard<std::mutex> lock(g_mutex);
  ++g_progress.resets;
}

}  // namespace penumbra::reference
