#include "core/Progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>

namespace og {
namespace {

volatile std::sig_atomic_t gStopSignal = 0;

extern "C" void onStopSignal(int signo) { gStopSignal = signo; }

}  // namespace

Progress::Progress(std::string label, std::int64_t total, bool enabled, std::FILE* out,
                   double plainIntervalS)
    : label_(std::move(label)),
      total_(std::max<std::int64_t>(total, 0)),
      enabled_(enabled && out != nullptr),
      out_(out),
      plainIntervalS_(plainIntervalS),
      start_(Clock::now()),
      lastDraw_(start_) {
  tty_ = enabled_ && ::isatty(::fileno(out_)) != 0;
}

Progress::~Progress() { finish(); }

double Progress::itemsPerSecond() const {
  const double s = std::chrono::duration<double>(Clock::now() - start_).count();
  return s > 0.0 ? static_cast<double>(done_) / s : 0.0;
}

std::string Progress::formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--";
  const auto total = static_cast<long long>(std::llround(seconds));
  const long long h = total / 3600, m = total / 60 % 60, s = total % 60;
  char text[48];
  if (h > 0)
    std::snprintf(text, sizeof text, "%lldh%02lldm%02llds", h, m, s);
  else if (m > 0)
    std::snprintf(text, sizeof text, "%lldm%02llds", m, s);
  else
    std::snprintf(text, sizeof text, "%llds", s);
  return text;
}

void Progress::advance(std::int64_t count) {
  done_ += count;
  if (!enabled_) return;
  const double since = std::chrono::duration<double>(Clock::now() - lastDraw_).count();
  if (since >= (tty_ ? 0.1 : plainIntervalS_)) draw(false);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void Progress::draw(bool final) {
  lastDraw_ = Clock::now();
  const double rate = itemsPerSecond();
  const double eta = rate > 0.0 ? static_cast<double>(total_ - done_) / rate : -1.0;
  const double fraction = total_ > 0 ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0;
  char stats[160];
  std::snprintf(stats, sizeof stats, "%lld/%lld frames  %.2f frames/s  %s %s",
                static_cast<long long>(done_), static_cast<long long>(total_), rate,
                final ? "took" : "ETA",
                formatDuration(final ? std::chrono::duration<double>(lastDraw_ - start_).count() : eta)
                    .c_str());
  if (tty_) {
    constexpr int kWidth = 30;
    const int filled = std::clamp(static_cast<int>(fraction * kWidth), 0, kWidth);
    // \r and clear-to-end-of-line: redraw in place.
    std::fprintf(out_, "\r%s [%s%s] %s\x1b[K%s", label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), stats,
                 final ? "\n" : "");
  } else {
    std::fprintf(out_, "%s: %s\n", label_.c_str(), stats);
  }
  std::fflush(out_);
}

void installStopHandlers() {
  gStopSignal = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // a second Ctrl-C kills at once
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool stopRequested() { return gStopSignal != 0; }
int stopSignal() { return static_cast<int>(gStopSignal); }

}  // namespace og
