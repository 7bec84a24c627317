#include "core/AtomicFile.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/Error.hpp"

namespace og {
namespace fs = std::filesystem;

namespace {
fs::path directoryOf(const fs::path& target) {
  const fs::path parent = target.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

fs::path temporaryBeside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Keep the extension last so libraries that pick a format by extension still work.
  std::string name = ".";  // built piecewise: GCC 12 -O2 warns falsely on one long chain
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  name += target.extension().string();
  return directoryOf(target) / name;
}
}  // namespace

void checkOutputWritable(const fs::path& target) {
  if (target.empty()) throw InputError("output path is empty");
  const fs::path dir = directoryOf(target);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(target.string() + ": directory '" + dir.string() + "' does not exist");
  if (fs::is_directory(target, ec))
    throw InputError(target.string() + ": is a directory, expected a file name");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(target.string() + ": directory '" + dir.string() +
                     "' is not writable: " + std::strerror(errno));
}

void writeFileAtomically(const fs::path& target,
                         const std::function<void(const fs::path& tmp)>& write) {
  checkOutputWritable(target);
  const fs::path tmp = temporaryBeside(target);
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw InputError(target.string() + ": cannot rename temporary file into place: " +
                     ec.message());
  }
}

}  // namespace og
