#pragma once
// A private scratch directory for work files (the benchmarks' generated inputs and outputs):
// created under the system's temporary directory, removed with everything in it when the
// object goes, errors on removal ignored (nothing of the user's lives there).
#include <filesystem>
#include <string>
#include <system_error>

namespace og::core {

class ScratchDirectory {
 public:
  /// Creates <temp>/<prefix><unique>; `unique` distinguishes concurrent users (e.g. the pid).
  ScratchDirectory(const std::string& prefix, const std::string& unique)
      : path_(std::filesystem::temp_directory_path() / (prefix + unique)) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace og::core
