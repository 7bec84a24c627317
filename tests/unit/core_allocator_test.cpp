// core/Allocator and src/core/MallocConf.cpp: the executables run on jemalloc with its large
// blocks on transparent huge pages (docs/performance.md, "Page faults").
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "core/Allocator.hpp"

#ifdef OG_JEMALLOC
namespace {

/// The kernel's transparent huge page mode ("always", "madvise", "never"), "" if unknown.
std::string thpMode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t open = all.find('['), close = all.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : all.substr(open + 1, close - open - 1);
}

/// Field `name` ("VmFlags:", "AnonHugePages:") of the mapping of this process that holds
/// `address` (/proc/self/smaps): the rest of its line, or nullopt where there is none.
std::optional<std::string> smapsField(const void* address, const std::string& name) {
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
    if (inside && line.rfind(name, 0) == 0) return line.substr(name.size());
  }
  return std::nullopt;
}

}  // namespace

TEST(Allocator, ExecutablesRunOnJemallocAskingForHugePages) {
  const og::core::AllocatorInfo info = og::core::allocatorInfo();
  EXPECT_EQ(info.name.rfind("jemalloc ", 0), 0u) << info.name;
  if (std::getenv("MALLOC_CONF") != nullptr) GTEST_SKIP() << "MALLOC_CONF is set: it overrides the built-in options";
  const std::string mode = thpMode();
  if (mode.empty()) GTEST_SKIP() << "no transparent huge pages here (jemalloc says 'not supported')";
  // The executable's malloc_conf was read: without it jemalloc's default is "default".
  EXPECT_EQ(info.hugePages, "always");
  const std::string summary = og::core::allocatorSummary();
  EXPECT_TRUE(summary.ends_with(" (thp:always)") && summary.find('-') == std::string::npos) << summary;
}

TEST(Allocator, LargeBlocksAreMarkedForHugePages) {
  const std::string mode = thpMode();
  if (mode != "always" && mode != "madvise") GTEST_SKIP() << "transparent huge pages are '" << mode << "' here";
  if (std::getenv("MALLOC_CONF") != nullptr) GTEST_SKIP() << "MALLOC_CONF is set";
  constexpr std::size_t kBytes = std::size_t{64} << 20;
  void* block = std::malloc(kBytes);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, kBytes);
  const void* middle = static_cast<char*>(block) + kBytes / 2;
  const std::optional<std::string> flags = smapsField(middle, "VmFlags:");
  const std::optional<std::string> huge = smapsField(middle, "AnonHugePages:");
  std::free(block);
  ASSERT_TRUE(flags.has_value()) << "the block's mapping is not in /proc/self/smaps";
  // "hg": the mapping was marked MADV_HUGEPAGE (in "madvise" mode nothing else asks for huge
  // pages). Whether the kernel found free 2 MiB pages at the fault depends on its memory's
  // fragmentation: printed, not asserted.
  EXPECT_NE((*flags + " ").find(" hg "), std::string::npos) << "VmFlags:" << *flags;
  std::printf("64 MiB block: AnonHugePages:%s\n", huge.value_or(" (none)").c_str());
}
#else
TEST(Allocator, TheCLibrarysWithoutJemalloc) {
  EXPECT_EQ(og::core::allocatorSummary(), "glibc malloc");
}
#endif
