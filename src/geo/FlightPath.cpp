#include "geo/FlightPath.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Error.hpp"

namespace og::geo {
namespace {

const GeographicLib::Geodesic& wgs84() { return GeographicLib::Geodesic::WGS84(); }

struct LatLon {
  double lat = 0, lon = 0;
};

/// The point a fraction `u` of the way from a to b along their geodesic.
LatLon geodesicLerp(const LatLon& a, const LatLon& b, double u) {
  double s12 = 0, azi1 = 0, azi2 = 0;
  wgs84().Inverse(a.lat, a.lon, b.lat, b.lon, s12, azi1, azi2);
  LatLon p;
  wgs84().Direct(a.lat, a.lon, azi1, u * s12, p.lat, p.lon);
  return p;
}

bool restsAtStart(Easing e) { return e == Easing::EaseIn || e == Easing::EaseInOut; }
bool restsAtEnd(Easing e) { return e == Easing::EaseOut || e == Easing::EaseInOut; }

/// Shape-preserving tangent at an interior point from the slopes d0, d1 of the intervals of
/// lengths h0, h1 before and after it: the weighted harmonic mean of Fritsch & Butland /
/// Brodlie (as in PCHIP). It is zero at extrema and never more than 3x either slope, which
/// keeps a monotone stretch monotone.
double harmonicTangent(double d0, double d1, double h0, double h1) {
  if (d0 * d1 <= 0.0) return 0.0;
  const double w1 = 2.0 * h1 + h0, w2 = h1 + 2.0 * h0;
  return (w1 + w2) / (w1 / d0 + w2 / d1);
}

}  // namespace

std::optional<Easing> parseEasing(std::string_view name) {
  if (name == "smooth") return Easing::Smooth;
  if (name == "ease-in") return Easing::EaseIn;
  if (name == "ease-out") return Easing::EaseOut;
  if (name == "ease-in-out") return Easing::EaseInOut;
  return std::nullopt;
}

const char* easingName(Easing e) {
  switch (e) {
    case Easing::Smooth: return "smooth";
    case Easing::EaseIn: return "ease-in";
    case Easing::EaseOut: return "ease-out";
    case Easing::EaseInOut: return "ease-in-out";
  }
  return "smooth";
}

double FlightPath::Channel::eval(std::size_t k, double u, double dt) const {
  // Cubic Hermite basis on u in [0, 1]; slopes are per second, hence the dt.
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * value[k] + (u3 - 2 * u2 + u) * dt * slope[k] +
         (-2 * u3 + 3 * u2) * value[k + 1] + (u3 - u2) * dt * slope[k + 1];
}

FlightPath::FlightPath(std::vector<Keyframe> keyframes) : keys_(std::move(keyframes)) {
  if (keys_.empty()) throw InputError("a flight path needs at least one keyframe");
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const std::string name = "keyframe " + std::to_string(k + 1) + ": ";
    if (auto problem = validatePose(keys_[k].pose)) throw InputError(name + *problem);
    if (!std::isfinite(keys_[k].timeS)) throw InputError(name + "time must be finite");
    if (k > 0 && !(keys_[k].timeS > keys_[k - 1].timeS))
      throw InputError(name + "time must be later than the previous keyframe's");
  }
  const std::size_t n = keys_.size();

  // Log space needs a positive argument: measure heights from a floor 1 m below the lowest
  // keyframe or the ellipsoid, whichever is lower (heights may be negative where the sea or
  // land lies below the ellipsoid).
  double lowest = 0.0;
  for (const auto& k : keys_) lowest = std::min(lowest, k.pose.position.heightM);
  heightFloorM_ = lowest - 1.0;

  for (Channel* c : {&logHeight_, &heading_, &pitch_, &roll_, &fov_}) {
    c->value.resize(n);
    c->slope.assign(n, 0.0);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const CameraPose& p = keys_[k].pose;
    logHeight_.value[k] = std::log(p.position.heightM - heightFloorM_);
    // Unwrap so each step is the shortest arc: 350 -> 10 goes up through 360 (= 0).
    heading_.value[k] = k == 0 ? p.headingDeg
                               : heading_.value[k - 1] +
                                     std::remainder(p.headingDeg - keys_[k - 1].pose.headingDeg, 360.0);
    pitch_.value[k] = p.pitchDeg;
    roll_.value[k] = p.rollDeg;
    fov_.value[k] = p.verticalFovDeg;
  }
  if (n == 1) return;

  auto atRest = [&](std::size_t k) {
    return (k + 1 < n && restsAtStart(keys_[k].easing)) || (k > 0 && restsAtEnd(keys_[k - 1].easing));
  };
  auto interval = [&](std::size_t k) { return keys_[k + 1].timeS - keys_[k].timeS; };

  // Scalar channels.
  for (Channel* c : {&logHeight_, &heading_, &pitch_, &roll_, &fov_}) {
    for (std::size_t k = 0; k < n; ++k) {
      if (atRest(k)) continue;
      if (k == 0) {
        c->slope[k] = (c->value[1] - c->value[0]) / interval(0);  // chord: a lone segment is linear
      } else if (k == n - 1) {
        c->slope[k] = (c->value[k] - c->value[k - 1]) / interval(k - 1);
      } else {
        const double h0 = interval(k - 1), h1 = interval(k);
        c->slope[k] = harmonicTangent((c->value[k] - c->value[k - 1]) / h0,
                                      (c->value[k + 1] - c->value[k]) / h1, h0, h1);
      }
    }
  }

  // Ground track: a velocity (speed along the ground, azimuth) per keyframe, then Bézier
  // control points one third of an interval along it, reached along geodesics.
  std::vector<double> speed(n, 0.0), azimuth(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const Geodetic& p = keys_[k].pose.position;
    double sOut = 0, aziOut = 0, sIn = 0, aziBack = 0, unused = 0;
    if (k + 1 < n) {
      const Geodetic& q = keys_[k + 1].pose.position;
      wgs84().Inverse(p.latitudeDeg, p.longitudeDeg, q.latitudeDeg, q.longitudeDeg, sOut, aziOut, unused);
    }
    if (k > 0) {
      const Geodetic& q = keys_[k - 1].pose.position;
      wgs84().Inverse(p.latitudeDeg, p.longitudeDeg, q.latitudeDeg, q.longitudeDeg, sIn, aziBack, unused);
    }
    if (atRest(k)) continue;
    constexpr double kSameSpotM = 1e-3;
    if (k == 0) {
      speed[k] = sOut / interval(0);
      azimuth[k] = aziOut;
    } else if (k == n - 1) {
      speed[k] = sIn / interval(k - 1);
      azimuth[k] = aziBack + 180.0;
    } else if (sIn > kSameSpotM && sOut > kSameSpotM) {
      // Direction: bisect the arriving and leaving directions in the local tangent plane;
      // speed: the harmonic tangent, reduced in turns (zero when the path doubles back).
      const double rad = std::numbers::pi / 180.0;
      const double ex = std::sin(aziOut * rad) - std::sin(aziBack * rad);
      const double ny = std::cos(aziOut * rad) - std::cos(aziBack * rad);
      const double len = std::hypot(ex, ny);
      if (len > 1e-9) {
        const double h0 = interval(k - 1), h1 = interval(k);
        speed[k] = harmonicTangent(sIn / h0, sOut / h1, h0, h1) * len / 2.0;
        azimuth[k] = std::atan2(ex, ny) / rad;
      }
    }
  }
  segments_.resize(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double third = interval(k) / 3.0;
    const Geodetic& a = keys_[k].pose.position;
    const Geodetic& b = keys_[k + 1].pose.position;
    Segment& s = segments_[k];
    wgs84().Direct(a.latitudeDeg, a.longitudeDeg, azimuth[k], speed[k] * third, s.latC1, s.lonC1);
    wgs84().Direct(b.latitudeDeg, b.longitudeDeg, azimuth[k + 1] + 180.0, speed[k + 1] * third,
                   s.latC2, s.lonC2);
  }
}

CameraPose FlightPath::at(double t) const {
  CameraPose pose = keys_.front().pose;
  if (keys_.size() == 1) return pose;
  t = std::clamp(t, startS(), endS());
  // The segment [k, k+1] holding t (the last one for t == endS).
  const auto after = std::upper_bound(keys_.begin() + 1, keys_.end() - 1, t,
                                      [](double v, const Keyframe& key) { return v < key.timeS; });
  const auto k = static_cast<std::size_t>(after - keys_.begin()) - 1;
  const double dt = keys_[k + 1].timeS - keys_[k].timeS;
  const double u = std::clamp((t - keys_[k].timeS) / dt, 0.0, 1.0);

  // De Casteljau with geodesic interpolation: a cubic Bézier on the ellipsoid.
  const Segment& s = segments_[k];
  const Geodetic& a = keys_[k].pose.position;
  const Geodetic& b = keys_[k + 1].pose.position;
  const LatLon p0{a.latitudeDeg, a.longitudeDeg}, p1{s.latC1, s.lonC1}, p2{s.latC2, s.lonC2},
      p3{b.latitudeDeg, b.longitudeDeg};
  const LatLon q0 = geodesicLerp(p0, p1, u), q1 = geodesicLerp(p1, p2, u), q2 = geodesicLerp(p2, p3, u);
  const LatLon r = geodesicLerp(geodesicLerp(q0, q1, u), geodesicLerp(q1, q2, u), u);

  pose.position = {r.lat, r.lon, std::exp(logHeight_.eval(k, u, dt)) + heightFloorM_};
  // exp(log(h)) is not always h: keyframe heights come back exactly (e.g. 2 m, not 2.0000000001).
  if (u == 0.0) pose.position.heightM = a.heightM;
  if (u == 1.0) pose.position.heightM = b.heightM;
  const double heading = std::fmod(heading_.eval(k, u, dt), 360.0);
  pose.headingDeg = heading < 0.0 ? heading + 360.0 : heading;
  pose.pitchDeg = std::clamp(pitch_.eval(k, u, dt), -90.0, 90.0);
  pose.rollDeg = std::clamp(roll_.eval(k, u, dt), -180.0, 180.0);
  pose.verticalFovDeg = fov_.eval(k, u, dt);
  return pose;
}

}  // namespace og::geo
