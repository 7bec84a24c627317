#include "core/Allocator.hpp"

#ifdef OG_JEMALLOC
#include <jemalloc/jemalloc.h>
#endif

namespace og::core {

AllocatorInfo allocatorInfo() {
#ifdef OG_JEMALLOC
  AllocatorInfo info;
  const char* version = nullptr;
  std::size_t size = sizeof(version);
  info.name = mallctl("version", &version, &size, nullptr, 0) == 0 && version != nullptr
                  ? std::string("jemalloc ") + version
                  : "jemalloc";
  const char* thp = nullptr;
  size = sizeof(thp);
  if (mallctl("opt.thp", &thp, &size, nullptr, 0) == 0 && thp != nullptr) info.hugePages = thp;
  return info;
#else
  return {"glibc malloc", ""};
#endif
}

std::string allocatorSummary() {
  const AllocatorInfo info = allocatorInfo();
  // "jemalloc 5.3.0-0-g54ea…": the release without git's suffix.
  std::string name = info.name;
  if (const std::size_t dash = name.find('-'); dash != std::string::npos) name.resize(dash);
  return info.hugePages.empty() ? name : name + " (thp:" + info.hugePages + ")";
}

}  // namespace og::core
