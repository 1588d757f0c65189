#pragma once
// Contract: parallelFor(count, work) calls work(i) once for every i in [0, count) on up to
// hardware_concurrency() threads (at most 8; none when count is small), thread t taking every T-th
// index. Results are deterministic as long as work(i) writes only what belongs to i: the split changes
// which thread runs an index, never what it computes. A thread that cannot be started leaves its
// share to the caller. The first exception (lowest thread) is rethrown after every thread finished.
// POSIX threads rather than std::thread: std::thread's destructor references std::terminate, which
// the library must never reference (tests/support/check_no_process_exit.sh). glibc >= 2.34 (Debian 12)
// has them in libc itself, so no link flag is needed.
#include <pthread.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace hp {
namespace detail {
struct ParallelShare {
  void (*run)(void* context, std::size_t thread);
  void* context;
  std::size_t thread;
};

inline void* runParallelShare(void* share) {
  auto* s = static_cast<ParallelShare*>(share);
  s->run(s->context, s->thread);
  return nullptr;
}
}  // namespace detail

template <typename Work>
void parallelFor(std::size_t count, Work&& work, std::size_t minPerThread = 16) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::min<std::size_t>({cores, 8, std::max<std::size_t>(1, count / minPerThread)});
  struct Context {
    Work& work;
    std::size_t count, threads;
    std::vector<std::exception_ptr> errors;
  } context{work, count, threads, std::vector<std::exception_ptr>(threads)};
  auto run = [](void* c, std::size_t t) {
    auto& ctx = *static_cast<Context*>(c);
    try {
      for (std::size_t i = t; i < ctx.count; i += ctx.threads) ctx.work(i);
    } catch (...) {
      ctx.errors[t] = std::current_exception();
    }
  };
  std::vector<detail::ParallelShare> shares(threads);
  std::vector<pthread_t> ids(threads);
  std::vector<bool> started(threads, false);
  for (std::size_t t = 1; t < threads; ++t) {
    shares[t] = {run, &context, t};
    started[t] = pthread_create(&ids[t], nullptr, detail::runParallelShare, &shares[t]) == 0;
  }
  run(&context, 0);
  for (std::size_t t = 1; t < threads; ++t)
    if (started[t]) pthread_join(ids[t], nullptr);
    else run(&context, t);
  for (const auto& e : context.errors)
    if (e) std::rethrow_exception(e);
}
}  // namespace hp
