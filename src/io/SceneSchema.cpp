#include "io/SceneSchema.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "core/Error.hpp"
#include "io/SceneTables.hpp"

namespace og::io {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

SceneField field(std::string_view section, std::string_view key, FieldType type, std::string_view unit,
                 std::string_view label) {
  SceneField f;
  f.section = section;
  f.key = key;
  f.type = type;
  f.unit = unit;
  f.label = label;
  return f;
}

// Accessors of the common kinds of settings.
SceneField number(std::string_view section, std::string_view key, std::string_view unit,
                  std::string_view label, double SceneSettings::*member) {
  SceneField f = field(section, key, FieldType::Number, unit, label);
  f.get = [member](const SceneSettings& s) -> FieldValue { return s.*member; };
  f.set = [member](SceneSettings& s, const FieldValue& v) { s.*member = std::get<double>(v); };
  return f;
}

SceneField ranged(SceneField f, double min, double max, bool minOpen = false) {
  f.min = min;
  f.max = max;
  f.minOpen = minOpen;
  return f;
}

// `ref(s)` is the setting in s, for const and non-const s alike.
template <class Ref>
SceneField camera(std::string_view key, std::string_view unit, Ref ref) {
  // Checked as a whole by geo::validatePose (its messages name latitude, pitch, ...).
  SceneField f = field("camera", key, FieldType::Number, unit, key);
  f.get = [ref](const SceneSettings& s) -> FieldValue { return ref(s); };
  f.set = [ref](SceneSettings& s, const FieldValue& v) { ref(s) = std::get<double>(v); };
  return f;
}

SceneField optionalNumber(std::string_view section, std::string_view key, std::string_view unit,
                          std::string_view label, std::optional<double> SceneSettings::*member) {
  SceneField f = field(section, key, FieldType::Number, unit, label);
  f.get = [member](const SceneSettings& s) -> FieldValue {
    if (const auto& v = s.*member) return *v;
    return std::monostate{};
  };
  f.set = [member](SceneSettings& s, const FieldValue& v) {
    if (const double* d = std::get_if<double>(&v)) s.*member = *d;
    else (s.*member).reset();
  };
  return f;
}

SceneField text(std::string_view section, std::string_view key, std::string_view label,
                std::string SceneSettings::*member, std::vector<std::string_view> choices) {
  SceneField f = field(section, key, FieldType::Text, "", label);
  f.choices = std::move(choices);
  f.get = [member](const SceneSettings& s) -> FieldValue { return s.*member; };
  f.set = [member](SceneSettings& s, const FieldValue& v) { s.*member = std::get<std::string>(v); };
  return f;
}

SceneField rgb(std::string_view key, std::string_view unit, glm::dvec3 atmosphere::Parameters::*member) {
  SceneField f = field("atmosphere", key, FieldType::Triple, unit, key);
  f.get = [member](const SceneSettings& s) -> FieldValue { return s.atmosphere.*member; };
  f.set = [member](SceneSettings& s, const FieldValue& v) { s.atmosphere.*member = std::get<glm::dvec3>(v); };
  return f;
}

SceneField atmosphereNumber(std::string_view key, std::string_view unit, double atmosphere::Parameters::*member) {
  // Ranges: atmosphere::validate checks the parameters as a whole.
  SceneField f = field("atmosphere", key, FieldType::Number, unit, key);
  f.get = [member](const SceneSettings& s) -> FieldValue { return s.atmosphere.*member; };
  f.set = [member](SceneSettings& s, const FieldValue& v) { s.atmosphere.*member = std::get<double>(v); };
  return f;
}

std::vector<SceneField> cameraFields() {
  return {camera("latitude_deg", "deg", [](auto& s) -> auto& { return s.camera.position.latitudeDeg; }),
          camera("longitude_deg", "deg", [](auto& s) -> auto& { return s.camera.position.longitudeDeg; }),
          camera("height_m", "m", [](auto& s) -> auto& { return s.camera.position.heightM; }),
          camera("heading_deg", "deg", [](auto& s) -> auto& { return s.camera.headingDeg; }),
          camera("pitch_deg", "deg", [](auto& s) -> auto& { return s.camera.pitchDeg; }),
          camera("roll_deg", "deg", [](auto& s) -> auto& { return s.camera.rollDeg; }),
          camera("fov_deg", "deg", [](auto& s) -> auto& { return s.camera.verticalFovDeg; })};
}

std::vector<SceneField> sunFields() {
  SceneField time = field("sun", "time", FieldType::Time, "", "time");
  time.legacyPathKey = "time";
  time.get = [](const SceneSettings& s) -> FieldValue {
    if (s.time) return s.time->toIso8601();
    return std::monostate{};
  };
  time.set = [](SceneSettings& s, const FieldValue& v) {
    const std::string* t = std::get_if<std::string>(&v);
    s.time = t ? UtcTime::parseIso8601(*t) : std::nullopt;
  };
  SceneField elevation = ranged(
      optionalNumber("sun", "elevation_deg", "deg", "Sun elevation", &SceneSettings::sunElevationDeg), -90, 90);
  elevation.legacyPathKey = "sun_elevation_deg";
  SceneField azimuth = ranged(
      optionalNumber("sun", "azimuth_deg", "deg", "Sun azimuth", &SceneSettings::sunAzimuthDeg), -720, 720);
  azimuth.legacyPathKey = "sun_azimuth_deg";
  // record/view: UTC seconds per second of path; the Sun and timed wind layers follow this
  // clock, the waves keep real time. Written only when not real time (1).
  SceneField lapse = ranged(number("sun", "time_lapse", "", "time lapse", &SceneSettings::timeLapse), 0, 1e6);
  lapse.legacyPathKey = "time_lapse";
  lapse.get = [](const SceneSettings& s) -> FieldValue {
    if (s.timeLapse == 1.0) return std::monostate{};
    return s.timeLapse;
  };
  lapse.set = [](SceneSettings& s, const FieldValue& v) {
    const double* d = std::get_if<double>(&v);
    s.timeLapse = d ? *d : 1.0;
  };
  return {time, elevation, azimuth, lapse};
}

std::vector<SceneField> imageFields() {
  auto size = [](std::string_view key, int SceneSettings::*member) {
    SceneField f = field("image", key, FieldType::Integer, "px", "image size");
    f.legacyPathKey = key;
    f.get = [member](const SceneSettings& s) -> FieldValue { return std::int64_t{s.*member}; };
    f.set = [member](SceneSettings& s, const FieldValue& v) { s.*member = static_cast<int>(std::get<std::int64_t>(v)); };
    return ranged(f, 1, 16384);
  };
  SceneField exposure = ranged(number("image", "exposure", "", "exposure", &SceneSettings::exposure), 0, 1e9, true);
  exposure.legacyPathKey = "exposure";
  SceneField samples = field("image", "samples", FieldType::Samples, "", "samples per pixel");
  samples.legacyPathKey = "samples";
  samples.get = [](const SceneSettings& s) -> FieldValue { return std::int64_t{s.samples}; };
  samples.set = [](SceneSettings& s, const FieldValue& v) { s.samples = static_cast<int>(std::get<std::int64_t>(v)); };
  return {size("width", &SceneSettings::width), size("height", &SceneSettings::height), exposure, samples};
}

std::vector<SceneField> oceanFields() {
  SceneField model = text("ocean", "model", "ocean model", &SceneSettings::oceanModel, {"bruneton", "classic"});
  model.legacyPathKey = "ocean_model";
  SceneField speed = ranged(number("ocean", "wind_speed_ms", "m/s", "wind speed", &SceneSettings::windSpeedMs), 0, 50);
  speed.legacyPathKey = "wind_speed_ms";
  // Meteorological: where the wind comes from, clockwise from north.
  SceneField from = ranged(number("ocean", "wind_from_deg", "deg", "wind direction", &SceneSettings::windFromDeg), -720, 720);
  from.aliases = {"wind_direction_deg"};
  from.legacyPathKey = "wind_direction_deg";
  SceneField clock = ranged(number("ocean", "time_s", "s", "simulation time", &SceneSettings::simulationTimeS), -1e9, 1e9);
  SceneField seed = field("ocean", "seed", FieldType::Integer, "", "seed");
  seed.min = 0;
  seed.max = 9223372036854775807.0;
  seed.get = [](const SceneSettings& s) -> FieldValue { return static_cast<std::int64_t>(s.waveSeed); };
  seed.set = [](SceneSettings& s, const FieldValue& v) { s.waveSeed = static_cast<std::uint64_t>(std::get<std::int64_t>(v)); };
  return {model, speed, from, clock, seed};
}

std::vector<SceneField> layerFields() {
  SceneField wind = field("layers", "wind", FieldType::TextList, "", "wind layers");
  wind.legacyPathKey = "wind_layers";
  wind.get = [](const SceneSettings& s) -> FieldValue { return s.windLayers; };
  wind.set = [](SceneSettings& s, const FieldValue& v) { s.windLayers = std::get<std::vector<std::string>>(v); };
  SceneField elevation = field("layers", "elevation", FieldType::Text, "", "elevation layer");
  elevation.legacyPathKey = "elevation_layer";
  elevation.get = [](const SceneSettings& s) -> FieldValue {
    if (s.elevationLayer.empty()) return std::monostate{};
    return s.elevationLayer;
  };
  elevation.set = [](SceneSettings& s, const FieldValue& v) {
    const std::string* t = std::get_if<std::string>(&v);
    s.elevationLayer = t ? *t : std::string();
  };
  // Georeferenced imagery draped over the land, bottom first; empty: the embedded Blue Marble.
  SceneField imagery = field("layers", "imagery", FieldType::TextList, "", "imagery layers");
  imagery.legacyPathKey = "imagery_layers";
  imagery.get = [](const SceneSettings& s) -> FieldValue {
    if (s.imageryLayers.empty()) return std::monostate{};
    return s.imageryLayers;
  };
  imagery.set = [](SceneSettings& s, const FieldValue& v) {
    const auto* list = std::get_if<std::vector<std::string>>(&v);
    s.imageryLayers = list ? *list : std::vector<std::string>();
  };
  SceneField backend = text("gl", "backend", "GL backend", &SceneSettings::glBackend, {"auto", "egl", "osmesa"});
  // ETOPO5's -10 m shallow-bank placeholder (data/ShallowBanks.hpp): auto = the embedded
  // default corrected, etopo5-banks = any layer, none = as the file has it.
  SceneField correction = text("layers", "elevation_correction", "elevation correction",
                               &SceneSettings::elevationCorrection, {"auto", "etopo5-banks", "none"});
  return {wind, elevation, correction, imagery, backend};
}

std::vector<SceneField> atmosphereFields() {
  using P = atmosphere::Parameters;
  SceneField sunRadius = field("atmosphere", "sun_angular_radius_deg", FieldType::Number, "deg", "sun_angular_radius_deg");
  sunRadius.get = [](const SceneSettings& s) -> FieldValue { return s.atmosphere.sunAngularRadiusRad * kDegPerRad; };
  sunRadius.set = [](SceneSettings& s, const FieldValue& v) {
    s.atmosphere.sunAngularRadiusRad = std::get<double>(v) / kDegPerRad;
  };
  SceneField orders = field("atmosphere", "scattering_orders", FieldType::Integer, "", "scattering_orders");
  orders.get = [](const SceneSettings& s) -> FieldValue { return std::int64_t{s.atmosphere.scatteringOrders}; };
  orders.set = [](SceneSettings& s, const FieldValue& v) {
    s.atmosphere.scatteringOrders = static_cast<int>(std::get<std::int64_t>(v));
  };
  return {rgb("solar_irradiance", "", &P::solarIrradiance),
          rgb("rayleigh_scattering", "1/m", &P::rayleighScattering),
          atmosphereNumber("rayleigh_scale_height_m", "m", &P::rayleighScaleHeightM),
          rgb("mie_scattering", "1/m", &P::mieScattering),
          rgb("mie_extinction", "1/m", &P::mieExtinction),
          atmosphereNumber("mie_scale_height_m", "m", &P::mieScaleHeightM),
          atmosphereNumber("mie_phase_g", "", &P::miePhaseG),
          rgb("ozone_absorption", "1/m", &P::ozoneAbsorption),
          atmosphereNumber("ozone_center_altitude_m", "m", &P::ozoneCenterAltitudeM),
          atmosphereNumber("ozone_half_width_m", "m", &P::ozoneHalfWidthM),
          rgb("ground_albedo", "", &P::groundAlbedo),
          sunRadius,
          atmosphereNumber("bottom_radius_m", "m", &P::bottomRadiusM),
          atmosphereNumber("thickness_m", "m", &P::thicknessM),
          atmosphereNumber("mu_s_min", "", &P::muSMin),
          ranged(orders, 1, 16384)};
}

std::string decimal(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string rangeText(const SceneField& f) {
  std::string r(f.minOpen ? "(" : "[");
  r.append(decimal(f.min)).append(", ").append(decimal(f.max)).append("]");
  if (!f.unit.empty()) r.append(" ").append(f.unit);
  return r;
}

bool inRange(const SceneField& f, double v) {
  return std::isfinite(v) && (f.minOpen ? v > f.min : v >= f.min) && v <= f.max;
}

}  // namespace

std::optional<int> parseSampleCount(std::string_view text) {
  if (text == "auto") return kAutoSamples;
  for (const int n : {1, 2, 4, 8})
    if (text == std::to_string(n)) return n;
  return std::nullopt;
}

const std::vector<SceneField>& sceneSchema() {
  static const std::vector<SceneField> schema = [] {
    std::vector<SceneField> all;
    for (auto part : {cameraFields(), sunFields(), imageFields(), oceanFields(), layerFields(), atmosphereFields()})
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }();
  return schema;
}

std::optional<std::string> checkField(const SceneField& f, const FieldValue& value, bool byKey) {
  const std::string name = byKey ? std::string("'").append(f.key).append("'") : std::string(f.label);
  if (std::holds_alternative<std::monostate>(value)) return std::nullopt;
  switch (f.type) {
    case FieldType::Number:
      if (!inRange(f, std::get<double>(value))) return name + " must be within " + rangeText(f);
      break;
    case FieldType::Integer:
      if (!inRange(f, static_cast<double>(std::get<std::int64_t>(value))))
        return name + " must be within " + rangeText(f);
      break;
    case FieldType::Triple:
      for (int i = 0; i < 3; ++i)
        if (!inRange(f, std::get<glm::dvec3>(value)[i])) return name + " must be within " + rangeText(f);
      break;
    case FieldType::Samples: {
      const std::int64_t n = std::get<std::int64_t>(value);
      if (n < 0 || n > 8 || !isValidSampleCount(static_cast<int>(n)))
        return name + " must be " + std::string(kSampleCountChoices) + (byKey ? "" : ", not " + std::to_string(n));
      break;
    }
    case FieldType::Time: {
      const std::string& t = std::get<std::string>(value);
      if (!UtcTime::parseIso8601(t)) return name + " is not an ISO-8601 UTC time: '" + t + "'";
      break;
    }
    case FieldType::Text: {
      if (f.choices.empty()) break;
      const std::string& t = std::get<std::string>(value);
      std::string list;
      for (const std::string_view c : f.choices) {
        if (c == t) return std::nullopt;
        list.append(list.empty() ? "" : ", ").append(c);
      }
      return name + " must be one of " + list + ", not '" + t + "'";
    }
    case FieldType::TextList: break;
  }
  return std::nullopt;
}

void validateScene(const SceneSettings& s, const std::string& origin) {
  const std::string prefix = origin.empty() ? "" : origin + ": ";
  if (auto problem = geo::validatePose(s.camera)) throw InputError(prefix + *problem);
  for (const SceneField& f : sceneSchema())
    if (auto problem = checkField(f, f.get(s), false)) throw InputError(prefix + *problem);
  if (s.time && (s.sunElevationDeg || s.sunAzimuthDeg))
    throw InputError(prefix + "give either a time or Sun elevation/azimuth, not both");
  if (auto problem = atmosphere::validate(s.atmosphere))
    throw InputError(prefix + "[atmosphere]: " + *problem);
}

namespace {
using detail::tomlNumber;
using detail::tomlString;

std::string tomlValue(const SceneField& f, const FieldValue& v) {
  if (f.type == FieldType::Samples && std::get<std::int64_t>(v) == kAutoSamples) return "\"auto\"";
  if (const double* d = std::get_if<double>(&v)) return tomlNumber(*d);
  if (const std::int64_t* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const std::string* t = std::get_if<std::string>(&v)) return tomlString(*t);
  if (const glm::dvec3* c = std::get_if<glm::dvec3>(&v))
    return std::string("[").append(tomlNumber(c->x)).append(", ").append(tomlNumber(c->y)).append(", ")
        .append(tomlNumber(c->z)).append("]");
  std::string list = "[";
  for (const std::string& item : std::get<std::vector<std::string>>(v))
    list.append(list.size() > 1 ? ", " : "").append(tomlString(item));
  return list + "]";
}
}  // namespace

std::string sceneToml(const SceneSettings& s, std::string_view prefix, bool withCamera) {
  const SceneSettings earth;
  bool customAtmosphere = false;
  for (const SceneField& f : sceneSchema())
    customAtmosphere |= f.section == "atmosphere" && f.get(s) != f.get(earth);
  std::ostringstream t;
  std::string_view section;
  for (const SceneField& f : sceneSchema()) {
    if (f.section == "camera" && !withCamera) continue;
    if (f.section == "atmosphere" && !customAtmosphere) continue;
    const FieldValue v = f.get(s);
    if (std::holds_alternative<std::monostate>(v)) continue;
    if (f.section != section) {
      t << (t.tellp() > 0 ? "\n" : "") << "[" << prefix << f.section << "]\n";
      section = f.section;
    }
    t << f.key << " = " << tomlValue(f, v) << "\n";
  }
  return t.str();
}

}  // namespace og::io
