// The golden model's one thread pool: the banded renderer, the parallel triangle setup and the
// lab's scenes all run on it.
#pragma once

#include <functional>

namespace zb {

// `threads`, or every core when it is 0 or less.
int resolve_threads(int threads);

// Runs work(i) for i in [0, n): i = 0 on the calling thread, the others on threads of their
// own (or on the caller, when no more threads can be had). Rethrows the exception of the
// lowest-numbered worker that threw, after all have finished.
void run_workers(int n, const std::function<void(int)>& work);

}  // namespace zb
