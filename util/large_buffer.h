#pragma once
// The one buffer type for the program's large arrays of plain values (a form-factor matrix, a
// plot's pixels, a glare table's quadrature): a fixed number of elements, made either
// uninitialised (LargeBuffer<T>::uninitialised: the owner writes every element before reading
// it) or filled with one value (LargeBuffer<T>::filled). Blocks of 512 KiB or more are mapped
// 2 MiB-aligned with transparent huge pages requested (madvise): a page fault costs about 11 us
// on the virtual machines this runs on, so a megabyte in 4 kB pages costs 2.7 ms the first time
// it is touched, in huge pages 0.1 to 0.2 ms; a block of 512 KiB rounded up to one huge page
// still costs less than its 128 small ones. Measured on whole runs, without them the office
// example takes 1.18 x the CPU time and the open plan 1.12 x. Smaller
// blocks come from malloc as usual, and so does every block where the system offers no
// transparent huge pages (then a mapping of its own would fault its small pages in afresh each
// time, where malloc's arenas reuse what was freed).
// Owners keep a LargeBuffer as private storage and hand out spans of it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace luxgrid {

constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;
constexpr std::size_t kHugePageMinBytes = std::size_t(512) << 10;

inline std::size_t huge_page_rounded(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

// Whether the system gives transparent huge pages to a mapping that asks (madvise): the
// setting in /sys/kernel/mm/transparent_hugepage/enabled is "[always]" or "[madvise]". Read once.
inline bool huge_pages_on_request() {
#if defined(__linux__)
  static const bool on = [] {
    std::FILE* f = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f) return false;
    char text[128] = {};
    const std::size_t n = std::fread(text, 1, sizeof text - 1, f);
    std::fclose(f);
    const std::string_view setting(text, n);
    return setting.find("[always]") != std::string_view::npos ||
           setting.find("[madvise]") != std::string_view::npos;
  }();
  return on;
#else
  return false;
#endif
}

inline bool mapped_on_its_own(std::size_t bytes) {
  return bytes >= kHugePageMinBytes && huge_pages_on_request();
}

// Blocks of kHugePageMinBytes or more are mapped on their own (mmap, 2 MiB-aligned, released by
// munmap when freed), not taken from malloc's arenas: an arena hands back memory it has touched
// before in 4 kB pages, or grows in them. Throws std::bad_alloc. Released by
// release_huge_pages with the same size.
inline void* allocate_huge_pages(std::size_t bytes) {
  if (!mapped_on_its_own(bytes)) {
    if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
    throw std::bad_alloc();
  }
#if defined(__linux__)
  const std::size_t rounded = huge_page_rounded(bytes);
  // One huge page more than asked, to cut an aligned block out of it.
  void* m = mmap(nullptr, rounded + kHugePageBytes, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) throw std::bad_alloc();
  auto* base = static_cast<char*>(m);
  const std::size_t misalignment = reinterpret_cast<std::uintptr_t>(base) % kHugePageBytes;
  const std::size_t head = misalignment ? kHugePageBytes - misalignment : 0;
  if (head) munmap(base, head);
  const std::size_t tail = kHugePageBytes - head;
  if (tail) munmap(base + head + rounded, tail);
  madvise(base + head, rounded, MADV_HUGEPAGE);  // advice only: without THP the pages are small
  return base + head;
#else
  if (void* p = std::malloc(bytes)) return p;
  throw std::bad_alloc();
#endif
}

inline void release_huge_pages(void* p, std::size_t bytes) noexcept {
#if defined(__linux__)
  if (mapped_on_its_own(bytes)) {
    munmap(p, huge_page_rounded(bytes));
    return;
  }
#endif
  std::free(p);
}

// A fixed-size array of trivially copyable T in memory from allocate_huge_pages. Move-only.
template <class T>
class LargeBuffer {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "LargeBuffer holds plain values: nothing is constructed or destroyed");

 public:
  LargeBuffer() = default;
  // `count` elements whose values are indeterminate until written.
  static LargeBuffer uninitialised(std::size_t count) { return LargeBuffer(count); }
  // `count` copies of `value`.
  static LargeBuffer filled(std::size_t count, const T& value) {
    LargeBuffer b(count);
    std::fill(b.data_, b.data_ + count, value);
    return b;
  }
  LargeBuffer(LargeBuffer&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  LargeBuffer& operator=(LargeBuffer&& other) noexcept {
    if (this != &other) {
      release();
      data_ = std::exchange(other.data_, nullptr);
      size_ = std::exchange(other.size_, 0);
    }
    return *this;
  }
  LargeBuffer(const LargeBuffer&) = delete;
  LargeBuffer& operator=(const LargeBuffer&) = delete;
  ~LargeBuffer() { release(); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  std::span<T> span() { return {data_, size_}; }
  std::span<const T> span() const { return {data_, size_}; }

 private:
  explicit LargeBuffer(std::size_t count)
      : data_(count ? static_cast<T*>(allocate_huge_pages(count * sizeof(T))) : nullptr),
        size_(count) {}
  void release() noexcept {
    if (data_) release_huge_pages(data_, size_ * sizeof(T));
  }
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace luxgrid
