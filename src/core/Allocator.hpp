#pragma once
// Which allocator the process runs on (jemalloc with transparent huge pages where built with
// it, CMake option OCEANGLOBE_JEMALLOC; the C library's under the sanitizers), for `bench`'s
// header and the tests (src/core/MallocConf.cpp says why).
#include <string>

namespace og::core {

struct AllocatorInfo {
  std::string name;        ///< "jemalloc 5.3.0-…" or "glibc malloc"
  std::string hugePages;   ///< jemalloc's "opt.thp" ("always", "default", "never", "not supported"), else ""
};

/// The running process's allocator and its huge-page option (MALLOC_CONF may have changed it).
AllocatorInfo allocatorInfo();

/// One line for a report: "jemalloc 5.3.0 (thp:always)" or "glibc malloc".
std::string allocatorSummary();

}  // namespace og::core
