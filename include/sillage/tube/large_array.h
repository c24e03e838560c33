#pragma once
// The allocator of a tube's slices and gates. A new array is written once
// over its whole length, and on Linux each fresh 4 KB page costs a fault
// that clears it (about 3 µs on a VM: 23 ns for each 32-byte slice of a
// tube, as much as computing it from an expression). Arrays of 2 MiB and
// more are mapped from a 2 MiB boundary, and their whole 2 MiB pieces are
// given to the kernel's transparent huge pages (madvise): one fault for 512
// pages, 5 to 6 times less per byte. The tail below 2 MiB keeps 4 KB pages,
// so an array occupies its size rounded to 4 KB, as on the heap. Smaller
// arrays, other systems and the AddressSanitizer builds (which watch heap
// arrays) use the heap. Freed arrays are recycled (below).
#include <cstddef>
#include <iterator>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace sillage::detail {

// Large pages from this size on (one huge page).
inline constexpr std::size_t kLargeArrayBytes = std::size_t{2} << 20;
// Freed arrays from this size on are kept for the next array of the same
// size (take_recycled, keep_recycled): a network, an automatic δ or a loop of the user's
// builds tubes of one TDomain again and again, and a block given back to the
// system (munmap, or the heap's trim of its top) costs its page faults
// again at the next use. At most kRecycledBytes are kept, the last freed
// first; not under AddressSanitizer (it would hide a use after free).
inline constexpr std::size_t kRecycledMinBytes = std::size_t{64} << 10;
inline constexpr std::size_t kRecycledBytes = std::size_t{64} << 20;
// A kept block of exactly `bytes`, or nullptr.
void* take_recycled(std::size_t bytes) noexcept;
// Keeps p (`bytes` long, from LargeArrayAllocator) if there is room; false if the
// caller must free it.
bool keep_recycled(void* p, std::size_t bytes) noexcept;
// The bytes kept now (tests).
std::size_t recycled_bytes() noexcept;
// Bytes of memory (from a 2 MiB boundary, huge pages advised) or nullptr if not
// available here (then the caller uses the heap); throws std::bad_alloc
// when mapping fails.
void* allocate_large(std::size_t bytes);
void deallocate_large(void* p, std::size_t bytes) noexcept;
// Whether allocate_large maps memory here (Linux, not under AddressSanitizer).
bool large_arrays_mapped();
// The memory an array of `bytes` (its capacity) occupies: whole 4 KB pages when mapped.
std::size_t large_array_footprint(std::size_t bytes);

// What an element is constructed from to be left unwritten (see
// unwritten_array): the array's new elements are then written by several
// threads at once, each touching its own pages first, instead of written
// twice (once here, once with their values) with all the page faults on one thread.
struct Unwritten {};

template <class T>
struct LargeArrayAllocator {
  using value_type = T;
  LargeArrayAllocator() = default;
  template <class U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    if (n * sizeof(T) >= kRecycledMinBytes) {
      if (void* p = take_recycled(n * sizeof(T))) return static_cast<T*>(p);
    }
    if (n * sizeof(T) >= kLargeArrayBytes) {
      if (void* p = allocate_large(n * sizeof(T))) return static_cast<T*>(p);
    }
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) >= kRecycledMinBytes && keep_recycled(p, n * sizeof(T))) return;
    if (n * sizeof(T) >= kLargeArrayBytes && large_arrays_mapped()) {
      deallocate_large(p, n * sizeof(T));
    } else {
      std::allocator<T>().deallocate(p, n);
    }
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  // Left for the caller to write (T is trivially copyable and destructible:
  // its objects begin with the storage).
  template <class U>
  void construct(U*, Unwritten) noexcept {}
  template <class U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept {
    return true;
  }
};

// Tags Unwritten, counted: the range a vector is constructed from.
class UnwrittenIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = Unwritten;
  using difference_type = std::ptrdiff_t;
  using pointer = const Unwritten*;
  using reference = Unwritten;
  UnwrittenIterator() = default;
  explicit UnwrittenIterator(std::size_t i) : i_(i) {}
  Unwritten operator*() const { return {}; }
  UnwrittenIterator& operator++() {
    ++i_;
    return *this;
  }
  UnwrittenIterator operator++(int) { return UnwrittenIterator(i_++); }
  bool operator==(const UnwrittenIterator&) const = default;

 private:
  std::size_t i_ = 0;
};

// An array of n elements not written: the caller writes every one of them
// before anything reads them.
template <class T>
std::vector<T, LargeArrayAllocator<T>> unwritten_array(std::size_t n) {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
  return std::vector<T, LargeArrayAllocator<T>>(UnwrittenIterator(0), UnwrittenIterator(n));
}

}  // namespace sillage::detail
