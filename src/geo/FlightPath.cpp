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

/// Cubic Hermite curve from p0 to p1 with end derivatives m0, m1 (per unit s), s in [0, 1].
glm::dvec4 hermite(const glm::dvec4& p0, const glm::dvec4& m0, const glm::dvec4& p1,
                   const glm::dvec4& m1, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

/// Tangents (per unit knot) of the centripetal Catmull-Rom curve through `p` at knots `tau`
/// (Barry & Goldman's form for uneven knots: the curve is C1 in its parameter), chords at the
/// ends, zero at a point that coincides with a neighbour (a hold). The last component (log
/// height) is limited as Fritsch & Carlson do, |m| <= 3 x the smaller neighbouring secant and
/// zero at an extremum, so it stays between its keyframe values on every segment.
std::vector<glm::dvec4> smoothTangents(const std::vector<glm::dvec4>& p, const std::vector<double>& tau) {
  const std::size_t n = p.size();
  std::vector<glm::dvec4> m(n, glm::dvec4(0.0));
  for (std::size_t k = 0; k < n; ++k) {
    const double h0 = k > 0 ? tau[k] - tau[k - 1] : 0.0, h1 = k + 1 < n ? tau[k + 1] - tau[k] : 0.0;
    if (k == 0 && h1 > 0.0) {
      m[k] = (p[1] - p[0]) / h1;
    } else if (k == n - 1 && h0 > 0.0) {
      m[k] = (p[k] - p[k - 1]) / h0;
    } else if (h0 > 0.0 && h1 > 0.0) {
      m[k] = (p[k] - p[k - 1]) / h0 - (p[k + 1] - p[k - 1]) / (h0 + h1) + (p[k + 1] - p[k]) / h1;
      const double d0 = (p[k].w - p[k - 1].w) / h0, d1 = (p[k + 1].w - p[k].w) / h1;
      const double limit = 3.0 * std::min(std::abs(d0), std::abs(d1));
      m[k].w = d0 * d1 <= 0.0 || m[k].w * d0 <= 0.0 ? 0.0 : std::copysign(std::min(std::abs(m[k].w), limit), d0);
    }
  }
  return m;
}

}  // namespace

std::optional<Easing> parseEasing(std::string_view name) {
  if (name == "smooth") return Easing::Smooth;
  if (name == "ease-in") return Easing::EaseIn;
  if (name == "ease-out") return Easing::EaseOut;
  if (name == "ease-in-out") return Easing::EaseInOut;
  return std::nullopt;
}

std::optional<Interpolation> parseInterpolation(std::string_view name) {
  if (name == "geodesic") return Interpolation::Geodesic;
  if (name == "smooth") return Interpolation::Smooth;
  return std::nullopt;
}

const char* interpolationName(Interpolation i) {
  return i == Interpolation::Smooth ? "smooth" : "geodesic";
}

Keyframe lookAtKeyframe(const LookAt& view, double rollDeg, double verticalFovDeg, double timeS,
                        Easing easing) {
  Keyframe k;
  k.lookAt = view;
  k.pose = cameraFromLookAt(view, rollDeg, verticalFovDeg);
  k.timeS = timeS;
  k.easing = easing;
  return k;
}

std::vector<Keyframe> orbitKeyframes(const Orbit& o) {
  if (auto problem = validateLookAt(o.start)) throw InputError("orbit: " + *problem);
  if (!std::isfinite(o.degrees) || o.degrees == 0.0 || std::abs(o.degrees) > 3600.0)
    throw InputError("orbit: degrees must be non-zero and within [-3600, 3600]");
  if (!std::isfinite(o.durationS) || !(o.durationS > 0.0))
    throw InputError("orbit: duration must be > 0 seconds");
  // Equal steps in heading at equal times: the shape-preserving tangents are then all equal,
  // so the heading turns at a constant rate (exactly linear) between the eased ends.
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(o.degrees) / 30.0 - 1e-9)));
  std::vector<Keyframe> keys;
  for (int i = 0; i <= steps; ++i) {
    LookAt view = o.start;
    view.headingDeg = std::fmod(o.start.headingDeg + o.degrees * i / steps, 360.0);
    Easing easing = Easing::Smooth;
    const bool in = i == 0 && restsAtStart(o.easing), out = i == steps - 1 && restsAtEnd(o.easing);
    if (in || out) easing = in && out ? Easing::EaseInOut : in ? Easing::EaseIn : Easing::EaseOut;
    keys.push_back(lookAtKeyframe(view, o.rollDeg, o.verticalFovDeg, o.durationS * i / steps, easing));
  }
  return keys;
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

FlightPath::FlightPath(std::vector<Keyframe> keyframes, Interpolation interpolation)
    : keys_(std::move(keyframes)), interpolation_(interpolation) {
  if (keys_.empty()) throw InputError("a flight path needs at least one keyframe");
  followsTargets_ = true;
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const std::string name = "keyframe " + std::to_string(k + 1) + ": ";
    Keyframe& key = keys_[k];
    if (key.lookAt) {
      if (auto problem = validateLookAt(*key.lookAt)) throw InputError(name + *problem);
      key.pose = cameraFromLookAt(*key.lookAt, key.pose.rollDeg, key.pose.verticalFovDeg);
    } else {
      followsTargets_ = false;
    }
    if (auto problem = validatePose(key.pose)) throw InputError(name + *problem);
    if (!std::isfinite(key.timeS)) throw InputError(name + "time must be finite");
    if (k > 0 && !(key.timeS > keys_[k - 1].timeS))
      throw InputError(name + "time must be later than the previous keyframe's");
  }
  const std::size_t n = keys_.size();
  for (const Keyframe& key : keys_) states_.push_back(stateOf(key));
  const std::vector<State>& states = states_;

  // Log space needs a positive argument: measure heights (ranges) from a floor 1 m below the
  // lowest keyframe or the ellipsoid (zero range), whichever is lower (heights may be negative
  // where the sea or land lies below the ellipsoid).
  double lowest = 0.0;
  for (const State& s : states) lowest = std::min(lowest, s.spanM);
  floorM_ = lowest - 1.0;

  for (Channel* c : {&logSpan_, &targetHeight_, &heading_, &pitch_, &roll_, &fov_, &progress_}) {
    c->value.resize(n);
    c->slope.assign(n, 0.0);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const State& s = states[k];
    logSpan_.value[k] = std::log(s.spanM - floorM_);
    targetHeight_.value[k] = s.targetHeightM;
    // Unwrap so each step is the shortest arc: 350 -> 10 goes up through 360 (= 0).
    heading_.value[k] = k == 0 ? s.headingDeg
                               : heading_.value[k - 1] +
                                     std::remainder(s.headingDeg - states[k - 1].headingDeg, 360.0);
    pitch_.value[k] = s.pitchDeg;
    roll_.value[k] = s.rollDeg;
    fov_.value[k] = s.fovDeg;
  }
  if (n == 1) return;
  for (Channel* c : {&logSpan_, &targetHeight_, &heading_, &pitch_, &roll_, &fov_}) fitChannel(*c);
  if (interpolation_ == Interpolation::Smooth)
    buildSmoothTrack(states);
  else
    buildGeodesicTrack(states);
}

FlightPath::State FlightPath::stateOf(const Keyframe& key) const {
  State s;
  const CameraPose& p = key.pose;
  s.rollDeg = p.rollDeg;
  s.fovDeg = p.verticalFovDeg;
  if (followsTargets_) {
    const LookAt& v = *key.lookAt;
    s.latDeg = v.target.latitudeDeg;
    s.lonDeg = v.target.longitudeDeg;
    s.spanM = v.rangeM;
    s.targetHeightM = v.target.heightM;
    s.headingDeg = v.headingDeg;
    s.pitchDeg = v.tiltDeg;
  } else {
    s.latDeg = p.position.latitudeDeg;
    s.lonDeg = p.position.longitudeDeg;
    s.spanM = p.position.heightM;
    s.headingDeg = p.headingDeg;
    s.pitchDeg = p.pitchDeg;
  }
  return s;
}

CameraPose FlightPath::poseOf(const State& s) const {
  if (followsTargets_) {
    LookAt view;
    view.target = {s.latDeg, s.lonDeg, s.targetHeightM};
    view.rangeM = std::max(s.spanM, 0.0);
    view.headingDeg = s.headingDeg;
    view.tiltDeg = std::clamp(s.pitchDeg, 0.0, 90.0);
    return cameraFromLookAt(view, std::clamp(s.rollDeg, -180.0, 180.0), s.fovDeg);
  }
  CameraPose pose;
  pose.position = {s.latDeg, s.lonDeg, s.spanM};
  const double heading = std::fmod(s.headingDeg, 360.0);
  pose.headingDeg = heading < 0.0 ? heading + 360.0 : heading;
  pose.pitchDeg = std::clamp(s.pitchDeg, -90.0, 90.0);
  pose.rollDeg = std::clamp(s.rollDeg, -180.0, 180.0);
  pose.verticalFovDeg = s.fovDeg;
  return pose;
}

bool FlightPath::atRest(std::size_t k) const {
  const std::size_t n = keys_.size();
  return (k + 1 < n && restsAtStart(keys_[k].easing)) || (k > 0 && restsAtEnd(keys_[k - 1].easing));
}

void FlightPath::fitChannel(Channel& c) const {
  const std::size_t n = keys_.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (atRest(k)) continue;
    if (k == 0) {
      c.slope[k] = (c.value[1] - c.value[0]) / interval(0);  // chord: a lone segment is linear
    } else if (k == n - 1) {
      c.slope[k] = (c.value[k] - c.value[k - 1]) / interval(k - 1);
    } else {
      const double h0 = interval(k - 1), h1 = interval(k);
      c.slope[k] = harmonicTangent((c.value[k] - c.value[k - 1]) / h0,
                                   (c.value[k + 1] - c.value[k]) / h1, h0, h1);
    }
  }
}

void FlightPath::buildGeodesicTrack(const std::vector<State>& states) {
  // Ground track: a velocity (speed along the ground, azimuth) per keyframe, then Bézier
  // control points one third of an interval along it, reached along geodesics.
  const std::size_t n = states.size();
  std::vector<double> speed(n, 0.0), azimuth(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const State& p = states[k];
    double sOut = 0, aziOut = 0, sIn = 0, aziBack = 0, unused = 0;
    if (k + 1 < n) wgs84().Inverse(p.latDeg, p.lonDeg, states[k + 1].latDeg, states[k + 1].lonDeg, sOut, aziOut, unused);
    if (k > 0) wgs84().Inverse(p.latDeg, p.lonDeg, states[k - 1].latDeg, states[k - 1].lonDeg, sIn, aziBack, unused);
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
    const State &a = states[k], &b = states[k + 1];
    Segment& s = segments_[k];
    wgs84().Direct(a.latDeg, a.lonDeg, azimuth[k], speed[k] * third, s.latC1, s.lonC1);
    wgs84().Direct(b.latDeg, b.lonDeg, azimuth[k + 1] + 180.0, speed[k + 1] * third, s.latC2, s.lonC2);
  }
}

void FlightPath::buildSmoothTrack(const std::vector<State>& states) {
  const std::size_t n = states.size();
  points_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    points_[k] = glm::dvec4(geodeticToEcef({states[k].latDeg, states[k].lonDeg, 0.0}), logSpan_.value[k]);
  // Centripetal knots: the square root of the perceived distance between keyframes, i.e. the
  // ground distance in units of their mean height (range) and the log of their height ratio.
  knots_.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double meanSpan = std::exp(0.5 * (points_[k].w + points_[k + 1].w));
    const double ground = glm::length(glm::dvec3(points_[k + 1]) - glm::dvec3(points_[k])) / meanSpan;
    knots_[k + 1] = knots_[k] + std::sqrt(std::hypot(ground, points_[k + 1].w - points_[k].w));
  }
  tangents_ = smoothTangents(points_, knots_);
  // The progress along the curve is a channel like the others: shape-preserving in time, at
  // rest where the easing says so, and still through a hold (two keyframes at one place).
  progress_.value = knots_;
  fitChannel(progress_);
}

CameraPose FlightPath::at(double t) const {
  if (keys_.size() == 1) return keys_.front().pose;
  t = std::clamp(t, startS(), endS());
  // The segment [k, k+1] holding t (the last one for t == endS).
  const auto after = std::upper_bound(keys_.begin() + 1, keys_.end() - 1, t,
                                      [](double v, const Keyframe& key) { return v < key.timeS; });
  const auto k = static_cast<std::size_t>(after - keys_.begin()) - 1;
  const double dt = interval(k);
  const double u = std::clamp((t - keys_[k].timeS) / dt, 0.0, 1.0);

  State s;
  double logSpan = 0.0;
  if (interpolation_ == Interpolation::Smooth) {
    const double tau = std::clamp(progress_.eval(k, u, dt), knots_[k], knots_[k + 1]);
    const double length = knots_[k + 1] - knots_[k];
    const glm::dvec4 p = length > 0.0 ? hermite(points_[k], tangents_[k] * length, points_[k + 1],
                                                tangents_[k + 1] * length, (tau - knots_[k]) / length)
                                      : points_[k];
    const Geodetic g = ecefToGeodetic(glm::dvec3(p));
    s.latDeg = g.latitudeDeg;
    s.lonDeg = g.longitudeDeg;
    logSpan = p.w;
  } else {
    // De Casteljau with geodesic interpolation: a cubic Bézier on the ellipsoid.
    const Segment& g = segments_[k];
    const LatLon p0{states_[k].latDeg, states_[k].lonDeg}, p1{g.latC1, g.lonC1}, p2{g.latC2, g.lonC2},
        p3{states_[k + 1].latDeg, states_[k + 1].lonDeg};
    const LatLon q0 = geodesicLerp(p0, p1, u), q1 = geodesicLerp(p1, p2, u), q2 = geodesicLerp(p2, p3, u);
    const LatLon r = geodesicLerp(geodesicLerp(q0, q1, u), geodesicLerp(q1, q2, u), u);
    s.latDeg = r.lat;
    s.lonDeg = r.lon;
    logSpan = logSpan_.eval(k, u, dt);
  }
  s.spanM = std::exp(logSpan) + floorM_;
  // exp(log(h)) is not always h: keyframe heights come back exactly (e.g. 2 m, not 2.0000000001).
  if (u == 0.0) s.spanM = states_[k].spanM;
  if (u == 1.0) s.spanM = states_[k + 1].spanM;
  s.targetHeightM = targetHeight_.eval(k, u, dt);
  s.headingDeg = heading_.eval(k, u, dt);
  s.pitchDeg = pitch_.eval(k, u, dt);
  s.rollDeg = roll_.eval(k, u, dt);
  s.fovDeg = fov_.eval(k, u, dt);
  return poseOf(s);
}

}  // namespace og::geo
