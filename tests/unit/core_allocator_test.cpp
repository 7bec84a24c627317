// core/Allocator and src/core/MallocConf.cpp: the executables run on jemalloc with its large
// blocks on transparent huge pages (docs/performance.md, "Page faults").
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "core/Allocator.hpp"

namespace {

/// The kernel's transparent huge page mode ("always", "madvise", "never"), "" if unknown.
std::string thpMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t open = all.find('['), close = all.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : all.substr(open + 1, close - open - 1);
}

/// AnonHugePages (KiB) of the mapping of this process that holds `address` (/proc/self/smaps).
long anonHugePagesKib(const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream head(line);
    if (line.find(':') == std::string::npos || line.find(':') > line.find(' ')) {  // a mapping's first line
      if (head >> std::hex >> from >> dash >> to && dash == '-') inside = a >= from && a < to;
      continue;
    }
    if (inside && line.rfind("AnonHugePages:", 0) == 0) return std::strtol(line.c_str() + 14, nullptr, 10);
  }
  return -1;
}

}  // namespace

#ifdef OG_JEMALLOC
TEST(Allocator, ExecutablesRunOnJemallocAskingForHugePages) {
  const og::core::AllocatorInfo info = og::core::allocatorInfo();
  EXPECT_EQ(info.name.rfind("jemalloc 5", 0), 0u) << info.name;
  if (std::getenv("MALLOC_CONF") != nullptr) GTEST_SKIP() << "MALLOC_CONF is set: it overrides the built-in options";
  // The executable's malloc_conf was read: without it jemalloc's default is "default".
  EXPECT_EQ(info.hugePages, "always");
  EXPECT_EQ(og::core::allocatorSummary(), "jemalloc 5.3.0 (thp:always)");
}

TEST(Allocator, LargeBlocksAreFaultedInOnHugePages) {
  const std::string mode = thpMode();
  if (mode != "always" && mode != "madvise") GTEST_SKIP() << "transparent huge pages are '" << mode << "' here";
  if (std::getenv("MALLOC_CONF") != nullptr) GTEST_SKIP() << "MALLOC_CONF is set";
  constexpr std::size_t kBytes = std::size_t{64} << 20;
  void* block = std::malloc(kBytes);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, kBytes);
  const long huge = anonHugePagesKib(static_cast<char*>(block) + kBytes / 2);
  std::free(block);
  // 4 KiB pages only (0) where the allocator did not ask for them ("madvise" mode).
  EXPECT_GT(huge, 0) << "no huge pages in a 64 MiB block";
}
#else
TEST(Allocator, TheCLibrarysWithoutJemalloc) {
  EXPECT_EQ(og::core::allocatorSummary(), "glibc malloc");
}
#endif
