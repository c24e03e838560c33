// The allocator of a tube's slices and gates: arrays of 2 MiB and more are
// mapped from a 2 MiB boundary (huge pages advised) where that is available, and
// behave as any vector's storage: written, grown, copied, freed. Freed arrays
// from 64 KiB on are kept (64 MiB at most) for the next array of their size.
#include <gtest/gtest.h>

#include <cstdint>
#include <new>
#include <vector>

#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"

using namespace sillage;

namespace {

constexpr std::size_t kLarge = detail::kLargeArrayBytes / sizeof(Interval);  // intervals in 2 MiB

}  // namespace

TEST(LargeArray, LargeArraysAreMappedOnTwoMegabyteBoundaries) {
  detail::LargeArrayAllocator<Interval> alloc;
  for (const std::size_t n : {kLarge, kLarge + 1, 3 * kLarge + 17}) {
    Interval* p = alloc.allocate(n);
    if (detail::large_arrays_mapped()) {
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t{2} << 20), 0u);
    }
    for (std::size_t i = 0; i < n; ++i) new (p + i) Interval(static_cast<double>(i));
    for (std::size_t i = 0; i < n; i += 4099) EXPECT_EQ(p[i], Interval(static_cast<double>(i)));
    EXPECT_EQ(p[n - 1], Interval(static_cast<double>(n - 1)));
    alloc.deallocate(p, n);
  }
}

TEST(LargeArray, SmallArraysComeFromTheHeap) {
  detail::LargeArrayAllocator<Interval> alloc;
  Interval* p = alloc.allocate(kLarge - 1);
  p[0] = Interval(1, 2), p[kLarge - 2] = Interval(3, 4);
  EXPECT_EQ(p[0], Interval(1, 2));
  EXPECT_EQ(p[kLarge - 2], Interval(3, 4));
  alloc.deallocate(p, kLarge - 1);
}

TEST(LargeArray, AVectorGrowsAcrossTheThresholdAndKeepsItsValues) {
  TubeArray a;
  for (std::size_t i = 0; i < 3 * kLarge; ++i) a.push_back(Interval(static_cast<double>(i), static_cast<double>(i) + 1));
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i].lb(), static_cast<double>(i)) << i;
  TubeArray b = a;  // a copy, then shrunk below the threshold
  EXPECT_EQ(a, b);
  b.resize(10);
  b.shrink_to_fit();
  EXPECT_EQ(b[9], a[9]);
  a.clear();
  a.shrink_to_fit();
  EXPECT_EQ(a.capacity(), 0u);
}

TEST(LargeArray, ALargeTubeIsTheSameAsItsSlicesSay) {
  // 200 000 slices: 3.2 MB of slices and of gates, on the mapped path.
  auto td = TDomain::create(0.0, 200.0, 0.001);
  ASSERT_GE(td->nb_slices() * sizeof(Interval), detail::kLargeArrayBytes);
  const Tube x(td, "t");
  for (std::size_t k = 0; k < td->nb_slices(); k += 997) {
    EXPECT_EQ(x.data().slices[k], Interval(td->t(k), td->t(k + 1))) << k;
    EXPECT_EQ(x.data().gates[k], Interval(td->t(k))) << k;
  }
  Tube y = x;  // copied on fresh mapped memory
  EXPECT_EQ(y.data().slices, x.data().slices);
  EXPECT_EQ(y.data().gates, x.data().gates);
  td->sample(100.00005);  // splits a slice in both tubes: the arrays grow by one
  EXPECT_EQ(x.nb_slices(), y.nb_slices());
  EXPECT_EQ(x.data().slices, y.data().slices);
}

TEST(LargeArray, MemoryBytesCountsTheWholePages) {
  // 200 000 slices: 3.2 MB per array, its size rounded to 4 KB pages when mapped.
  auto td = TDomain::create(0.0, 200.0, 0.001);
  const Tube x(td, Interval(0, 1));
  const std::size_t slices = x.data().slices.capacity() * sizeof(Interval);
  const std::size_t gates = x.data().gates.capacity() * sizeof(Interval);
  const std::size_t page = 4096;
  const std::size_t expected = detail::large_arrays_mapped()
                                   ? (slices + page - 1) / page * page + (gates + page - 1) / page * page
                                   : slices + gates;
  EXPECT_EQ(x.memory_bytes(), sizeof(TubeData) + expected);
  EXPECT_LE(x.memory_bytes(), 33 * td->nb_slices());  // 32 bytes per slice, as on the heap
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRecycles = false;  // AddressSanitizer watches every freed array
#else
constexpr bool kRecycles = true;
#endif

TEST(LargeArray, FreedArraysAreRecycledBySize) {
  detail::LargeArrayAllocator<Interval> alloc;
  const std::size_t n = 100000;  // 1.6 MB: from the heap
  for (const std::size_t size : {n, 2 * kLarge}) {
    Interval* p = alloc.allocate(size);
    const std::size_t before = detail::recycled_bytes();
    alloc.deallocate(p, size);
    EXPECT_EQ(detail::recycled_bytes(), before + (kRecycles ? size * sizeof(Interval) : 0));
    Interval* q = alloc.allocate(size);  // the same block back
    if (kRecycles) { EXPECT_EQ(q, p); }
    EXPECT_EQ(detail::recycled_bytes(), before);
    Interval* r = alloc.allocate(size + 1);  // another size: not that block
    EXPECT_NE(r, q);
    alloc.deallocate(r, size + 1);
    alloc.deallocate(q, size);
  }
  // Small arrays are left to the heap.
  const std::size_t small = detail::kRecycledMinBytes / sizeof(Interval) - 1;
  const std::size_t before = detail::recycled_bytes();
  alloc.deallocate(alloc.allocate(small), small);
  EXPECT_EQ(detail::recycled_bytes(), before);
}

TEST(LargeArray, AtMost64MegabytesAreKept) {
  detail::LargeArrayAllocator<Interval> alloc;
  const std::size_t n = 3 * kLarge;  // 6 MiB each: 21 of them are 126 MiB
  std::vector<Interval*> blocks;
  for (int i = 0; i < 21; ++i) blocks.push_back(alloc.allocate(n));
  for (Interval* p : blocks) alloc.deallocate(p, n);
  EXPECT_LE(detail::recycled_bytes(), detail::kRecycledBytes);
  if (kRecycles) { EXPECT_GT(detail::recycled_bytes(), detail::kRecycledBytes - n * sizeof(Interval)); }
  const std::size_t huge = detail::kRecycledBytes / sizeof(Interval) + 1;  // beyond the whole budget
  const std::size_t before = detail::recycled_bytes();
  alloc.deallocate(alloc.allocate(huge), huge);
  EXPECT_EQ(detail::recycled_bytes(), before);
}

TEST(LargeArray, ATubeOnARecycledBlockHoldsOnlyItsOwnValues) {
  auto td = TDomain::create(0.0, 100.0, 0.01);  // 10 000 slices: 160 kB arrays
  { const Tube old(td, Interval(5, 6)); }       // freed: its arrays are kept
  const Tube x(td, Interval(-1, 1));             // on them
  const Tube y(td, "t");                         // unwritten arrays, each element computed
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    ASSERT_EQ(x.data().slices[k], Interval(-1, 1)) << k;
    ASSERT_EQ(x.data().gates[k], Interval(-1, 1)) << k;
    ASSERT_EQ(y.data().slices[k], Interval(td->t(k), td->t(k + 1))) << k;
  }
  { const Tube old(td, Interval(5, 6)); }
  Tube z = y;  // a copy on a recycled block
  EXPECT_EQ(z.data().slices, y.data().slices);
  EXPECT_EQ(z.data().gates, y.data().gates);
}
