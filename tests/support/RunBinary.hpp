#pragma once
// Running the built oceanglobe binary from the CLI-tier tests: exit code, stdout and stderr,
// captured per test (CTest runs tests in parallel processes), and fresh scratch folders.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace og::test {

struct RunResult {
  int exitCode = -1;  ///< -1 when the process did not exit normally (killed by a signal)
  std::string out;
  std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// A fresh, empty folder for the current test: OG_TEST_OUT_DIR/group/test_name.
inline std::filesystem::path scratchDir(const std::string& group) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(OG_TEST_OUT_DIR) / group / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs a shell command line with no standard input; output is kept in
/// OG_TEST_OUT_DIR/group/logs/<test><tag>.stdout|.stderr for a look after a failure.
inline RunResult runCommand(const std::string& command, const std::string& group,
                            const std::string& tag = "") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(OG_TEST_OUT_DIR) / group / "logs";
  std::filesystem::create_directories(dir);
  const std::filesystem::path out = dir / (std::string(info->name()) + tag + ".stdout");
  const std::filesystem::path err = dir / (std::string(info->name()) + tag + ".stderr");
  const int status = std::system(
      (command + " >" + out.string() + " 2>" + err.string() + " </dev/null").c_str());
  RunResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

/// `oceanglobe ARGS`.
inline RunResult runOceanglobe(const std::string& args, const std::string& group,
                               const std::string& tag = "") {
  return runCommand(std::string(OG_BINARY) + " " + args, group, tag);
}

}  // namespace og::test
