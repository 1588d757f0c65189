#pragma once
// Contract: parallelFor(count, work) calls work(i) once for every i in [0, count) on up to
// hardware_concurrency() std::threads (at most 8; none when count is small), each taking every
// T-th index. Results are deterministic as long as work(i) writes only what belongs to i: the split
// changes which thread runs an index, never what it computes. The first exception (lowest thread)
// is rethrown after every thread has finished.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace hp {
template <typename Work>
void parallelFor(std::size_t count, Work&& work, std::size_t minPerThread = 16) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::min<std::size_t>({cores, 8, std::max<std::size_t>(1, count / minPerThread)});
  std::vector<std::exception_ptr> errors(threads);
  auto run = [&](std::size_t t) {
    try {
      for (std::size_t i = t; i < count; i += threads) work(i);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(run, t);
  run(0);
  for (auto& th : pool) th.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}
}  // namespace hp
