// CLI tier: `oceanglobe view` in a real window on a private Xvfb server (llvmpipe), driven by
// xdotool: the view moves when keys are held, P writes a screenshot (PNG + EXR), K appends the
// view to a path file `record` accepts (with the whole scene: --seed, --t), Esc exits 0. Skipped where Xvfb or xdotool is missing
// (scripts/install-deps.sh installs both).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "io/CameraPath.hpp"
#include "io/Image.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

bool haveProgram(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

// A child process killed (if still running) when the test ends, however it ends.
struct Child {
  pid_t pid = -1;
  ~Child() {
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }
  // Exit status once it exits within `timeout`, -1 on a signal, nullopt-like -2 on timeout.
  int waitExit(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(50ms);
    }
    return -2;
  }
};

// Runs `sh -c command` in the background (exec'd, so the pid is the command's own).
pid_t spawn(const std::string& command) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

// Starts Xvfb on the first free display (it reports the number through -displayfd).
bool startXvfb(Child& xvfb, std::string& display) {
  int fds[2];
  if (::pipe(fds) != 0) return false;
  xvfb.pid = ::fork();
  if (xvfb.pid == 0) {
    ::close(fds[0]);
    const std::string fd = std::to_string(fds[1]);
    ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "640x480x24", "-nolisten",
             "tcp", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  std::string number;
  char c = 0;
  while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  ::close(fds[0]);
  if (number.empty()) return false;
  display = ":" + number;
  return true;
}

std::string capture(const std::string& command) {
  std::string out;
  if (FILE* p = ::popen(command.c_str(), "r")) {
    std::array<char, 256> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), p) != nullptr) out += buffer.data();
    ::pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

bool waitFor(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(100ms);
  }
  return done();
}

std::size_t keyframesIn(const fs::path& file) {
  try {
    return fs::exists(file) ? og::io::readCameraPath(file).keyframes.size() : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

double meanAbsDifference(const og::io::ImageRgba8& a, const og::io::ImageRgba8& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
  return sum / static_cast<double>(a.pixels.size());
}

}  // namespace

TEST(View, FliesTakesScreenshotsWritesKeyframesAndQuitsOnEscape) {
  if (!haveProgram("Xvfb") || !haveProgram("xdotool"))
    GTEST_SKIP() << "Xvfb and xdotool are needed (scripts/install-deps.sh)";
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "view";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path flight = dir / "flight.toml";

  Child xvfb;
  std::string display;
  ASSERT_TRUE(startXvfb(xvfb, display)) << "Xvfb did not start";
  ::setenv("DISPLAY", display.c_str(), 1);

  // Looking straight down from 2000 km: holding W descends towards the sea.
  Child viewer;
  viewer.pid = spawn(std::string(OG_BINARY) + " view --width 320 --height 180 --lat 36 --lon -9 "
                     "--alt 2000000 --time 2024-06-20T15:00Z --seed 7 --t 2.5 --screenshot-dir " + dir.string() +
                     " --keyframes " + flight.string() + " >" + (dir / "view.stdout").string() +
                     " 2>" + (dir / "view.stderr").string());
  const std::string window = capture("timeout 30 xdotool search --sync --name 'oceanglobe view' | head -1");
  ASSERT_FALSE(window.empty()) << "no viewer window within 30 s";
  auto send = [&](const std::string& keys) {
    ASSERT_EQ(std::system(("xdotool " + keys).c_str()), 0) << keys;
  };

  // Keys are handled between frames; the files appear once the frame after them is drawn.
  send("key --window " + window + " p k");
  const fs::path shot1 = dir / "oceanglobe_0001.png";
  ASSERT_TRUE(waitFor([&] { return fs::exists(shot1); }, 30s)) << "no screenshot on P";
  EXPECT_TRUE(fs::exists(dir / "oceanglobe_0001.exr"));
  ASSERT_TRUE(waitFor([&] { return keyframesIn(flight) == 1; }, 10s)) << "no keyframe on K";

  send("keydown --window " + window + " w");
  std::this_thread::sleep_for(1500ms);
  send("keyup --window " + window + " w");
  send("key --window " + window + " p k");
  const fs::path shot2 = dir / "oceanglobe_0002.png";
  ASSERT_TRUE(waitFor([&] { return fs::exists(shot2); }, 20s)) << "no second screenshot";
  ASSERT_TRUE(waitFor([&] { return keyframesIn(flight) == 2; }, 10s)) << "no second keyframe";

  const og::io::ImageRgba8 before = og::io::readPng(shot1), after = og::io::readPng(shot2);
  EXPECT_EQ(before.width, 320);
  EXPECT_EQ(before.height, 180);
  ASSERT_EQ(after.pixels.size(), before.pixels.size());
  EXPECT_GT(meanAbsDifference(before, after), 2.0) << "the view did not change after holding W";
  const og::io::CameraPath path = og::io::readCameraPath(flight);  // what record reads
  ASSERT_EQ(path.keyframes.size(), 2u);
  EXPECT_LT(path.keyframes[1].pose.position.heightM, 0.9 * path.keyframes[0].pose.position.heightM);
  EXPECT_GT(path.keyframes[1].timeS, path.keyframes[0].timeS);
  // The viewer's scene is the one given (view --seed, --t), and K writes all of it.
  EXPECT_EQ(path.scene.waveSeed, 7u);
  EXPECT_EQ(path.scene.simulationTimeS, 2.5);

  send("key --window " + window + " Escape");
  EXPECT_EQ(viewer.waitExit(20s), 0) << "view did not exit 0 on Esc";
}

TEST(View, BadOutputPlacesExitTwoBeforeOpeningAWindow) {
  const fs::path dir = fs::path(OG_TEST_OUT_DIR) / "view-bad";
  fs::create_directories(dir);
  const std::string base = std::string(OG_BINARY) + " view --width 64 --height 36 ";
  const std::string quiet = " >/dev/null 2>" + (dir / "err").string();
  int status = std::system((base + "--screenshot-dir " + (dir / "missing").string() + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const fs::path bad = dir / "bad.toml";
  std::FILE* f = std::fopen(bad.string().c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("[[keyframe]]\nlatitude_deg = \"north\"\n", f);
  std::fclose(f);
  status = std::system((base + "--keyframes " + bad.string() + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);
  status = std::system((base + "--path " + (dir / "none.toml").string() + quiet).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);
}
