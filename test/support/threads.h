// Runs code with an exact number of threads, even on a machine with fewer cores: the
// tests that compare 1 and 2 threads must run 2 threads wherever CI runs them. An
// explicit arena has the slots; the global limit lets that many threads join it.
#ifndef DF_L1_TEST_SUPPORT_THREADS_H
#define DF_L1_TEST_SUPPORT_THREADS_H

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <utility>

namespace DF_L1_test {

template <class F>
auto with_threads(int threads, F&& f) -> decltype(f())
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  tbb::task_arena arena(threads);
  return arena.execute(std::forward<F>(f));
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_SUPPORT_THREADS_H
