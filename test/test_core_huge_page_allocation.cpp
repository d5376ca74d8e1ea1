// Tests of include/diffuv/core/huge_page_allocation.h, which this file
// includes for the whole test program: large blocks from `new` are advised
// onto huge pages, through every form of new. (That blocks under 4 MiB are
// not advised is not checked: glibc may place them in a heap region an
// earlier large block had advised.)
#include <diffuv/core/huge_page_allocation.h>

#include <gtest/gtest.h>

#include <sys/mman.h>

#include <cstdint>
#include <memory>
#include <new>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The kernel's transparent huge page mode: "always", "madvise" or "never"
// (the word in brackets), or "" where there is no such file.
std::string huge_page_mode()
{
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  const auto open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

// The THPeligible flag of the mapping that holds `address` in
// /proc/self/smaps: 1 where the kernel may back it with huge pages.
int huge_page_eligible(const void* address)
{
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream in("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while(std::getline(in, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if(range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
      continue;
    }
    if(inside && line.rfind("THPeligible:", 0) == 0) return std::stoi(line.substr(12));
  }
  return -1;
}

TEST(CoreHugePageAllocation, LargeBlocksAreAdvisedOntoHugePages)
{
#if !defined(DIFFUV_HUGE_PAGE_ALLOCATION_ACTIVE)
  GTEST_SKIP() << "no huge page advice in this build (a sanitizer, or not Linux)";
#else
  // A control: a mapping of our own, advised by hand. Where the kernel does
  // not show that as eligible (huge pages off, 'always' mode, no THPeligible
  // line), the advice cannot be seen either.
  const std::size_t control_bytes = std::size_t(8) << 20;
  void* control = mmap(nullptr, control_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(control, MAP_FAILED);
  const bool shows_advice = huge_page_mode() == "madvise" && huge_page_eligible(control) == 0 &&
                            madvise(control, control_bytes, MADV_HUGEPAGE) == 0 && huge_page_eligible(control) == 1;
  munmap(control, control_bytes);
  if(!shows_advice) GTEST_SKIP() << "this kernel does not show madvise(MADV_HUGEPAGE) in /proc/self/smaps";
  // 64 MiB: well above glibc's largest mmap threshold (32 MiB), so the block
  // is a mapping of its own and its flag is its own.
  std::vector<char> large(std::size_t(64) << 20, 1);
  EXPECT_EQ(huge_page_eligible(large.data() + large.size() / 2), 1);
  // The same through new[] and the nothrow form.
  std::unique_ptr<double[]> doubles(new double[std::size_t(8) << 20]);
  EXPECT_EQ(huge_page_eligible(doubles.get() + (std::size_t(4) << 20)), 1);
  std::unique_ptr<char[]> nothrow(new(std::nothrow) char[std::size_t(64) << 20]);
  ASSERT_NE(nothrow, nullptr);
  EXPECT_EQ(huge_page_eligible(nothrow.get() + (std::size_t(32) << 20)), 1);
#endif
}

} // namespace
