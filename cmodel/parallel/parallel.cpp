#include "parallel.h"

#include <algorithm>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace zb {

int resolve_threads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void run_workers(int n, const std::function<void(int)>& work) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(std::max(n, 0)));
  auto guarded = [&](int i) {
    try {
      work(i);
    } catch (...) {
      errors[size_t(i)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(size_t(n > 0 ? n - 1 : 0));
  int spawned = 1;
  try {
    for (; spawned < n; ++spawned) pool.emplace_back(guarded, spawned);
  } catch (const std::system_error&) {
    // No more threads to be had: the caller does the rest of the work itself.
  }
  if (n > 0) guarded(0);
  for (int i = spawned; i < n; ++i) guarded(i);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace zb
