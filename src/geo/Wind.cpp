#include "geo/Wind.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>

#include "core/Error.hpp"

namespace og::geo {
namespace {
constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// An angle in degrees within [0, 360).
double wrapDeg(double deg) {
  const double d = std::fmod(deg, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

// The whole string must be one number.
std::optional<double> parseNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return v;
}
}  // namespace

Wind Wind::blowingFrom(double speedMs, double fromDeg) { return {speedMs, wrapDeg(fromDeg + 180.0)}; }

Wind Wind::blowingTowards(double speedMs, double towardsDeg) { return {speedMs, wrapDeg(towardsDeg)}; }

Wind Wind::ofVector(WindVector w) {
  if (w.uMs == 0.0 && w.vMs == 0.0) return {0.0, 0.0};
  return {std::hypot(w.uMs, w.vMs), wrapDeg(std::atan2(w.uMs, w.vMs) / kRadPerDeg)};
}

double Wind::fromDeg() const { return wrapDeg(towardsDeg + 180.0); }

WindVector Wind::vector() const {
  const double a = towardsDeg * kRadPerDeg;
  return {speedMs * std::sin(a), speedMs * std::cos(a)};
}

Wind parseWindFlag(const std::string& text, double defaultFromDeg) {
  const std::size_t comma = text.find(',');
  const auto speed = parseNumber(text.substr(0, comma));
  const auto from = comma == std::string::npos ? std::optional(defaultFromDeg) : parseNumber(text.substr(comma + 1));
  if (!speed || !from) throw InputError("--wind: expected SPEED[,FROM] (two numbers), got '" + text + "'");
  if (!std::isfinite(*speed) || *speed < 0.0 || *speed > 50.0)
    throw InputError("--wind: wind speed must be within [0, 50] m/s, not '" + text + "'");
  if (!std::isfinite(*from) || std::abs(*from) > 720.0)
    throw InputError("--wind: wind direction must be within [-720, 720] degrees, not '" + text + "'");
  return Wind::blowingFrom(*speed, *from);
}

}  // namespace og::geo
