#include "sillage/tube/large_array.h"

#include <cstdint>
#include <mutex>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define SILLAGE_RECYCLE_ARRAYS 0
#else
#define SILLAGE_RECYCLE_ARRAYS 1
#endif

#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#include <sys/mman.h>
#define SILLAGE_LARGE_ARRAYS_MAPPED 1
#else
#define SILLAGE_LARGE_ARRAYS_MAPPED 0
#endif

namespace sillage::detail {

namespace {

constexpr std::size_t kPiece = std::size_t{2} << 20;  // one huge page
constexpr std::size_t kPage = 4096;

std::size_t pages(std::size_t bytes) { return (bytes + kPage - 1) / kPage * kPage; }

}  // namespace

bool large_arrays_mapped() { return SILLAGE_LARGE_ARRAYS_MAPPED; }

namespace {

// The freed arrays kept, the last freed at the back. A handful of blocks
// (at most kRecycledBytes / kRecycledMinBytes): a scan costs nothing next to
// the faults of one block.
struct Recycled {
  std::mutex m;
  std::vector<std::pair<void*, std::size_t>> blocks;
  std::size_t bytes = 0;
};

// Never destroyed: a tube freed by a static destructor after it still finds it.
Recycled& recycled() {
  static Recycled* r = new Recycled;
  return *r;
}

}  // namespace

void* take_recycled(std::size_t bytes) noexcept {
  if (!SILLAGE_RECYCLE_ARRAYS) return nullptr;
  Recycled& r = recycled();
  const std::lock_guard lock(r.m);
  for (std::size_t i = r.blocks.size(); i-- > 0;) {
    if (r.blocks[i].second != bytes) continue;
    void* p = r.blocks[i].first;
    r.blocks.erase(r.blocks.begin() + static_cast<std::ptrdiff_t>(i));
    r.bytes -= bytes;
    return p;
  }
  return nullptr;
}

bool keep_recycled(void* p, std::size_t bytes) noexcept {
  if (!SILLAGE_RECYCLE_ARRAYS || bytes > kRecycledBytes) return false;
  Recycled& r = recycled();
  const std::lock_guard lock(r.m);
  if (r.bytes + bytes > kRecycledBytes) return false;
  try {
    r.blocks.emplace_back(p, bytes);
  } catch (...) {  // no room for the entry: free the block instead
    return false;
  }
  r.bytes += bytes;
  return true;
}

std::size_t recycled_bytes() noexcept {
  Recycled& r = recycled();
  const std::lock_guard lock(r.m);
  return r.bytes;
}

std::size_t large_array_footprint(std::size_t bytes) {
  return bytes >= kLargeArrayBytes && large_arrays_mapped() ? pages(bytes) : bytes;
}

#if SILLAGE_LARGE_ARRAYS_MAPPED

void* allocate_large(std::size_t bytes) {
  const std::size_t len = pages(bytes);
  // Map one piece more, then unmap what is before the first 2 MiB boundary and after the array:
  // a huge page needs a 2 MiB-aligned range.
  void* raw = mmap(nullptr, len + kPiece, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto base = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (base + kPiece - 1) / kPiece * kPiece;
  if (aligned > base) munmap(raw, aligned - base);
  const std::uintptr_t end = base + len + kPiece;
  if (end > aligned + len) munmap(reinterpret_cast<void*>(aligned + len), end - (aligned + len));
  void* p = reinterpret_cast<void*>(aligned);
  // Advice only (without huge pages the memory works the same), on the whole pieces: a huge page
  // over the tail would occupy memory the array does not use.
  madvise(p, len / kPiece * kPiece, MADV_HUGEPAGE);
  return p;
}

void deallocate_large(void* p, std::size_t bytes) noexcept { munmap(p, pages(bytes)); }

#else

void* allocate_large(std::size_t) { return nullptr; }
void deallocate_large(void*, std::size_t) noexcept {}

#endif

}  // namespace sillage::detail
