#include "data/GridFile.hpp"

#include "data/TimeAxis.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <system_error>

#include "core/Error.hpp"
#include "data/GribFile.hpp"
#include "data/NetcdfFile.hpp"

namespace og::data {
namespace fs = std::filesystem;

std::unique_ptr<GridFile> openGridFile(const fs::path& file) {
  std::array<char, 8> head{};
  std::size_t got = 0;
  {
    std::error_code ec;
    if (fs::is_regular_file(file, ec)) {
      std::ifstream in(file, std::ios::binary);
      in.read(head.data(), head.size());
      got = static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0));
    }
  }
  if (detail::looksLikeGrib(std::string_view(head.data(), got))) return detail::openGrib(file);
  // Everything else goes to netCDF-C, which names what is wrong (missing, unknown format...).
  return detail::openNetcdf(detail::NetcdfFile::open(file));
}

std::unique_ptr<GridFile> openGridMemory(std::string_view bytes, const std::string& label) {
  if (detail::looksLikeGrib(bytes)) return detail::openGribMemory(bytes, label);
  return detail::openNetcdf(detail::NetcdfFile::openMemory(bytes, label));
}

LayerSpec parseLayerSpec(const std::string& spec) {
  if (spec.empty()) throw InputError("empty layer specification (expected FILE[:VARIABLES])");
  LayerSpec out;
  std::error_code ec;
  const std::size_t colon = spec.rfind(':');
  if (colon == std::string::npos || fs::exists(spec, ec) ||
      spec.find('/', colon) != std::string::npos) {
    out.file = spec;
    return out;
  }
  out.file = spec.substr(0, colon);
  if (out.file.empty()) throw InputError(spec + ": no file name before ':'");
  const std::string names = spec.substr(colon + 1);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = names.find(',', start);
    std::string name = names.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty())
      throw InputError(out.file.string() + ": empty variable name in '" + spec +
                       "' (expected FILE:VAR or FILE:U,V)");
    out.variables.push_back(std::move(name));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

StepChoice chooseSteps(const std::vector<UtcTime>& times, std::optional<UtcTime> time) {
  StepChoice c;
  if (times.size() < 2 || !time) return c;
  const double t = time->unixSeconds;
  if (t <= times.front().unixSeconds) return c;
  if (t >= times.back().unixSeconds) {
    c.first = c.second = times.size() - 1;
    return c;
  }
  // First step strictly after t; the axis is strictly increasing (validated on load).
  const auto after = std::upper_bound(times.begin(), times.end(), t,
                                      [](double v, const UtcTime& u) { return v < u.unixSeconds; });
  c.second = static_cast<std::size_t>(after - times.begin());
  c.first = c.second - 1;
  const double t0 = times[c.first].unixSeconds;
  const double t1 = times[c.second].unixSeconds;
  c.weight = (t - t0) / (t1 - t0);
  if (c.weight == 0.0) c.second = c.first;
  return c;
}

StepChoice chooseFieldSteps(const FieldDescription& field, std::optional<UtcTime> time) {
  return field.climatology ? detail::chooseClimatologySteps(field.times, time)
                           : chooseSteps(field.times, time);
}

std::string chooseField(const GridFile& file, const std::string& requested,
                        const std::vector<std::string>& preferredNames) {
  if (!requested.empty()) {
    (void)file.describe(requested);  // validates: exists, on latitude/longitude axes
    return requested;
  }
  const std::vector<FieldSummary> fields = file.fields();
  if (fields.size() == 1) return fields.front().name;
  for (const std::string& preferred : preferredNames)
    for (const FieldSummary& f : fields)
      if (f.name == preferred) return f.name;
  std::string names;
  for (const FieldSummary& f : fields) names += (names.empty() ? "" : ", ") + f.name;
  throw InputError(file.label() + ": several fields on latitude/longitude (" + names +
                   "); name the one to use");
}

}  // namespace og::data
