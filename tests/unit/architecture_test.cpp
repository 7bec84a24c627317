// The layering rules of docs/architecture.md that a compiler does not check: only src/gl talks
// to the window system and asks the driver who it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
// Files under src/ outside src/gl whose text contains `needle`.
std::vector<std::string> filesOutsideGlWith(const std::string& needle) {
  std::vector<std::string> found;
  const fs::path src = fs::path(OG_SOURCE_DIR) / "src";
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const fs::path rel = fs::relative(entry.path(), src);
    if (*rel.begin() == "gl") continue;
    std::ifstream in(entry.path());
    const std::string text(std::istreambuf_iterator<char>(in), {});
    if (text.find(needle) != std::string::npos) found.push_back(rel.string());
  }
  return found;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + " ";
  return s;
}
}  // namespace

TEST(Architecture, OnlyTheGlLibraryTouchesTheWindowSystemAndTheDriverName) {
  EXPECT_TRUE(filesOutsideGlWith("#include <GLFW").empty()) << joined(filesOutsideGlWith("#include <GLFW"));
  EXPECT_TRUE(filesOutsideGlWith("#include <EGL").empty()) << joined(filesOutsideGlWith("#include <EGL"));
  EXPECT_TRUE(filesOutsideGlWith("glGetString(GL_RENDERER").empty()) << joined(filesOutsideGlWith("glGetString(GL_RENDERER"));
  EXPECT_TRUE(filesOutsideGlWith("\"llvmpipe\"").empty()) << joined(filesOutsideGlWith("\"llvmpipe\""));
}
