// diffuv: large allocations advised onto transparent huge pages.
//
// Include this header in exactly one source file of a program (it defines
// the replaceable global `operator new` and `operator delete`); the diffuv
// tool, its tests and its benches do. Every allocation of at least 4 MiB
// made through `new` (so every large std::vector: a Surface_mesh's arrays, a
// soup, distance fields) is then advised with `madvise(MADV_HUGEPAGE)` before
// it is touched, so that Linux backs it with 2 MiB pages where the system's
// transparent huge pages are set to `madvise` (Debian's default) or
// `always`. Why: on the virtual machines measured here, touching fresh
// memory costs a fault per 4 KiB page, and reading a 1.1M-vertex OFF file
// spent half of its time in those faults (1.65 s, 0.82 s with huge pages;
// doc/performance.md, "Fresh memory on huge pages"). Memory is still taken
// with malloc() and given back with free(), so nothing else changes; where
// madvise() is missing or refuses, the advice is simply not taken. Under a
// sanitizer the header defines nothing (the sanitizer's own operators stay);
// where it does define them, DIFFUV_HUGE_PAGE_ALLOCATION_ACTIVE is defined.
// Aligned new (over-aligned types) is not replaced and gets no advice.
#ifndef DIFFUV_CORE_HUGE_PAGE_ALLOCATION_H
#define DIFFUV_CORE_HUGE_PAGE_ALLOCATION_H

// Sanitizers replace operator new themselves (GCC says so with
// __SANITIZE_*__, clang only through __has_feature).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || defined(__SANITIZE_HWADDRESS__)
#define DIFFUV_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(hwaddress_sanitizer)
#define DIFFUV_UNDER_SANITIZER 1
#endif
#endif

#if defined(__linux__) && !defined(DIFFUV_UNDER_SANITIZER) && !defined(DIFFUV_NO_HUGE_PAGE_ALLOCATION)
/// Defined where this header replaces operator new (Linux, no sanitizer,
/// DIFFUV_NO_HUGE_PAGE_ALLOCATION not defined).
#define DIFFUV_HUGE_PAGE_ALLOCATION_ACTIVE 1

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace diffuv {
namespace internal {

constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;
constexpr std::size_t huge_page_advice_from = std::size_t(4) << 20;

// malloc(), then the whole 2 MiB pages inside the block advised as huge.
inline void* allocate_advising_huge_pages(std::size_t bytes) noexcept
{
  void* block = std::malloc(bytes == 0 ? 1 : bytes);
  if(block != nullptr && bytes >= huge_page_advice_from) {
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t begin = (start + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
    const std::uintptr_t end = (start + bytes) & ~(huge_page_bytes - 1);
    if(end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
  return block;
}

// What operator new must do: on failure, call the new-handler and try
// again, or throw std::bad_alloc if there is none.
inline void* allocate_or_throw(std::size_t bytes)
{
  for(;;) {
    if(void* block = allocate_advising_huge_pages(bytes)) return block;
    const std::new_handler handler = std::get_new_handler();
    if(handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

inline void* allocate_or_null(std::size_t bytes) noexcept
{
  try {
    return allocate_or_throw(bytes);
  } catch(...) {
    return nullptr;
  }
}

} // namespace internal
} // namespace diffuv

void* operator new(std::size_t bytes) { return diffuv::internal::allocate_or_throw(bytes); }
void* operator new[](std::size_t bytes) { return diffuv::internal::allocate_or_throw(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept { return diffuv::internal::allocate_or_null(bytes); }
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept { return diffuv::internal::allocate_or_null(bytes); }
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { std::free(block); }

#endif

#endif // DIFFUV_CORE_HUGE_PAGE_ALLOCATION_H
