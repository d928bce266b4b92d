// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_PARALLEL_FOR_H
#define CGAL_DF_L1_SKELETON_INTERNAL_PARALLEL_FOR_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// f(begin, end) over consecutive ranges that cover [0, n), of about `grain` indices each
// with TBB (when ConcurrencyTag is Parallel_tag): for loops whose iterations can share
// scratch memory along a range.
template <class ConcurrencyTag, class Function>
void for_each_range(std::size_t n, const Function& f, std::size_t grain = 512)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#endif
  f(std::size_t(0), n);
}

// f(i) for i in [0, n), with TBB when ConcurrencyTag is Parallel_tag. Each f(i) must
// write only its own outputs, so that the result does not depend on the threads.
template <class ConcurrencyTag, class Function>
void for_each_index(std::size_t n, const Function& f, std::size_t grain = 512)
{
  for_each_range<ConcurrencyTag>(n, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      f(i);
  }, grain);
}

// f() and g(), at the same time with TBB when ConcurrencyTag is Parallel_tag; they must
// not write what the other reads.
template <class ConcurrencyTag, class F, class G>
void run_both(const F& f, const G& g)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_invoke(f, g);
    return;
  }
#endif
  f();
  g();
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_PARALLEL_FOR_H
