#include "io/SceneFile.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "core/Error.hpp"

namespace og::io {
namespace {

std::string where(const std::filesystem::path& file, const toml::source_region& r) {
  return file.string() + ":" + std::to_string(r.begin.line) + ": ";
}

double number(const std::filesystem::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<double>(); v && n.is_number()) {
    if (!std::isfinite(*v)) throw InputError(where(file, n.source()) + "'" + key + "' must be finite");
    return *v;
  }
  throw InputError(where(file, n.source()) + "'" + key + "' must be a number");
}

int integer(const std::filesystem::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<std::int64_t>(); v && n.is_integer()) {
    if (*v < 1 || *v > 16384)
      throw InputError(where(file, n.source()) + "'" + key + "' must be within [1, 16384]");
    return static_cast<int>(*v);
  }
  throw InputError(where(file, n.source()) + "'" + key + "' must be an integer");
}

glm::dvec3 triple(const std::filesystem::path& file, const toml::node& n, const std::string& key) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() != 3)
    throw InputError(where(file, n.source()) + "'" + key + "' must be an array of 3 numbers");
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) v[i] = number(file, *a->get(static_cast<std::size_t>(i)), key);
  return v;
}

// Multisampling counts the renderer takes (render::isValidSampleCount; io sits below render).
bool validSamples(std::int64_t n) { return n == 1 || n == 2 || n == 4 || n == 8; }

std::string text(const std::filesystem::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<std::string>(); v && n.is_string()) return *v;
  throw InputError(where(file, n.source()) + "'" + key + "' must be a string");
}

}  // namespace

SceneSettings readSceneFile(const std::filesystem::path& file, SceneSettings s) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    // toml++ says "File could not be opened for reading" for missing/unreadable files.
    throw InputError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
  using Setter = std::function<void(const toml::node&, const std::string&)>;
  auto num = [&](double& out) -> Setter {
    return [&](const toml::node& n, const std::string& k) { out = number(file, n, k); };
  };
  auto rgb = [&](glm::dvec3& out) -> Setter {
    return [&](const toml::node& n, const std::string& k) { out = triple(file, n, k); };
  };
  atmosphere::Parameters& atm = s.atmosphere;
  const std::map<std::string, std::map<std::string, Setter>> schema = {
      {"camera",
       {{"latitude_deg", num(s.camera.position.latitudeDeg)},
        {"longitude_deg", num(s.camera.position.longitudeDeg)},
        {"height_m", num(s.camera.position.heightM)},
        {"heading_deg", num(s.camera.headingDeg)},
        {"pitch_deg", num(s.camera.pitchDeg)},
        {"roll_deg", num(s.camera.rollDeg)},
        {"fov_deg", num(s.camera.verticalFovDeg)}}},
      {"sun",
       {{"time",
         [&](const toml::node& n, const std::string& k) {
           const std::string t = text(file, n, k);
           s.time = UtcTime::parseIso8601(t);
           if (!s.time)
             throw InputError(where(file, n.source()) + "'time' is not an ISO-8601 UTC time: '" +
                              t + "'");
         }},
        {"elevation_deg",
         [&](const toml::node& n, const std::string& k) { s.sunElevationDeg = number(file, n, k); }},
        {"azimuth_deg",
         [&](const toml::node& n, const std::string& k) { s.sunAzimuthDeg = number(file, n, k); }}}},
      {"image",
       {{"width", [&](const toml::node& n, const std::string& k) { s.width = integer(file, n, k); }},
        {"height", [&](const toml::node& n, const std::string& k) { s.height = integer(file, n, k); }},
        {"exposure", num(s.exposure)},
        {"samples",
         [&](const toml::node& n, const std::string& k) {
           if (n.is_string() && n.value<std::string>() == "auto") {
             s.samples = 0;
             return;
           }
           const auto v = n.value<std::int64_t>();
           if (!n.is_integer() || !v || !validSamples(*v))
             throw InputError(where(file, n.source()) + "'" + k + "' must be \"auto\", 1, 2, 4 or 8");
           s.samples = static_cast<int>(*v);
         }}}},
      {"ocean",
       {{"model",
         [&](const toml::node& n, const std::string& k) { s.oceanModel = text(file, n, k); }},
        {"wind_speed_ms", num(s.windSpeedMs)},
        {"wind_direction_deg", num(s.windFromDeg)},
        {"time_s", num(s.simulationTimeS)},
        {"seed",
         [&](const toml::node& n, const std::string& k) {
           const auto v = n.value<std::int64_t>();
           if (!n.is_integer() || !v || *v < 0)
             throw InputError(where(file, n.source()) + "'" + k + "' must be a non-negative integer");
           s.waveSeed = static_cast<std::uint64_t>(*v);
         }}}},
      {"layers",
       {{"wind",
         [&](const toml::node& n, const std::string& k) {
           const toml::array* list = n.as_array();
           if (list == nullptr)
             throw InputError(where(file, n.source()) + "'" + k + "' must be an array of strings");
           s.windLayers.clear();
           for (const toml::node& item : *list) s.windLayers.push_back(text(file, item, k));
         }},
        {"elevation",
         [&](const toml::node& n, const std::string& k) { s.elevationLayer = text(file, n, k); }},
        {"imagery",
         [&](const toml::node& n, const std::string& k) {
           const toml::array* list = n.as_array();
           if (list == nullptr)
             throw InputError(where(file, n.source()) + "'" + k + "' must be an array of strings");
           s.imageryLayers.clear();
           for (const toml::node& item : *list) s.imageryLayers.push_back(text(file, item, k));
         }}}},
      {"atmosphere",
       {{"solar_irradiance", rgb(atm.solarIrradiance)},
        {"rayleigh_scattering", rgb(atm.rayleighScattering)},
        {"rayleigh_scale_height_m", num(atm.rayleighScaleHeightM)},
        {"mie_scattering", rgb(atm.mieScattering)},
        {"mie_extinction", rgb(atm.mieExtinction)},
        {"mie_scale_height_m", num(atm.mieScaleHeightM)},
        {"mie_phase_g", num(atm.miePhaseG)},
        {"ozone_absorption", rgb(atm.ozoneAbsorption)},
        {"ozone_center_altitude_m", num(atm.ozoneCenterAltitudeM)},
        {"ozone_half_width_m", num(atm.ozoneHalfWidthM)},
        {"ground_albedo", rgb(atm.groundAlbedo)},
        {"sun_angular_radius_deg",
         [&](const toml::node& n, const std::string& k) {
           atm.sunAngularRadiusRad = number(file, n, k) * 3.14159265358979323846 / 180.0;
         }},
        {"bottom_radius_m", num(atm.bottomRadiusM)},
        {"thickness_m", num(atm.thicknessM)},
        {"mu_s_min", num(atm.muSMin)},
        {"scattering_orders",
         [&](const toml::node& n, const std::string& k) { atm.scatteringOrders = integer(file, n, k); }}}},
      {"gl",
       {{"backend",
         [&](const toml::node& n, const std::string& k) { s.glBackend = text(file, n, k); }}}},
  };
  for (const auto& [sectionKey, sectionNode] : root) {
    const std::string section(sectionKey.str());
    const auto it = schema.find(section);
    if (it == schema.end())
      throw InputError(where(file, sectionKey.source()) + "unknown section [" + section + "]");
    const toml::table* table = sectionNode.as_table();
    if (table == nullptr)
      throw InputError(where(file, sectionNode.source()) + "'" + section + "' must be a table");
    for (const auto& [key, value] : *table) {
      const std::string k(key.str());
      const auto setter = it->second.find(k);
      if (setter == it->second.end())
        throw InputError(where(file, key.source()) + "unknown key '" + k + "' in [" + section + "]");
      setter->second(value, k);
    }
  }
  validateScene(s, file.string());
  return s;
}

void validateScene(const SceneSettings& s, const std::string& origin) {
  const std::string prefix = origin.empty() ? "" : origin + ": ";
  if (auto problem = geo::validatePose(s.camera)) throw InputError(prefix + *problem);
  if (s.width < 1 || s.width > 16384 || s.height < 1 || s.height > 16384)
    throw InputError(prefix + "image size must be within [1, 16384] pixels");
  if (!std::isfinite(s.exposure) || s.exposure <= 0.0 || s.exposure > 1e9)
    throw InputError(prefix + "exposure must be a positive finite number");
  if (s.samples != 0 && !validSamples(s.samples))
    throw InputError(prefix + "samples per pixel must be auto, 1, 2, 4 or 8, not " + std::to_string(s.samples));
  if (s.time && (s.sunElevationDeg || s.sunAzimuthDeg))
    throw InputError(prefix + "give either a time or Sun elevation/azimuth, not both");
  if (s.sunElevationDeg && (!std::isfinite(*s.sunElevationDeg) || std::abs(*s.sunElevationDeg) > 90.0))
    throw InputError(prefix + "Sun elevation must be within [-90, 90] degrees");
  if (s.sunAzimuthDeg && (!std::isfinite(*s.sunAzimuthDeg) || std::abs(*s.sunAzimuthDeg) > 720.0))
    throw InputError(prefix + "Sun azimuth must be a finite number of degrees within [-720, 720]");
  if (s.oceanModel != "bruneton" && s.oceanModel != "classic")
    throw InputError(prefix + "ocean model must be bruneton or classic, not '" + s.oceanModel + "'");
  if (!std::isfinite(s.windSpeedMs) || s.windSpeedMs < 0.0 || s.windSpeedMs > 50.0)
    throw InputError(prefix + "wind speed must be within [0, 50] m/s");
  if (!std::isfinite(s.windFromDeg) || std::abs(s.windFromDeg) > 720.0)
    throw InputError(prefix + "wind direction must be a finite number of degrees within [-720, 720]");
  if (auto problem = atmosphere::validate(s.atmosphere))
    throw InputError(prefix + "[atmosphere]: " + *problem);
  if (!std::isfinite(s.simulationTimeS) || std::abs(s.simulationTimeS) > 1e9)
    throw InputError(prefix + "simulation time must be a finite number of seconds within [-1e9, 1e9]");
  if (s.glBackend != "auto" && s.glBackend != "egl" && s.glBackend != "osmesa")
    throw InputError(prefix + "GL backend must be auto, egl or osmesa, not '" + s.glBackend + "'");
}

}  // namespace og::io
