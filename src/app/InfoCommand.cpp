// oceanglobe info: what a data file holds, as the wind/elevation layers would read it.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/Commands.hpp"
#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/GridFile.hpp"
#include "data/WindField.hpp"

namespace og::app {
namespace {

struct InfoOptions {
  std::string spec;
  bool json = false;
};

struct VariableReport {
  data::FieldSummary summary;
  std::string role;  ///< "u", "v" or "field"
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  std::size_t valid = 0;
  std::size_t cells = 0;
};

/// The variables `info` reports: those named; else the wind pair; else the one scalar field
/// an elevation layer would pick; else every field on latitude/longitude axes.
std::vector<VariableReport> chooseVariables(const data::GridFile& file,
                                            const std::vector<std::string>& named) {
  std::vector<VariableReport> out;
  const auto add = [&](const std::string& name, const char* role) {
    VariableReport r;
    r.summary = file.describe(name).summary;
    r.role = role;
    out.push_back(std::move(r));
  };
  if (named.size() == 2) {
    const data::WindVariables w = data::chooseWindVariables(file, named);
    add(w.u, "u");
    add(w.v, "v");
    return out;
  }
  if (named.size() == 1) {
    add(named[0], "field");
    return out;
  }
  if (!named.empty())
    throw InputError(file.label() + ": name one field (FILE:VAR) or a wind pair (FILE:U,V)");
  try {
    const data::WindVariables w = data::chooseWindVariables(file, {});
    add(w.u, "u");
    add(w.v, "v");
    return out;
  } catch (const InputError&) {
    // not a wind file: fall through to scalar fields
  }
  try {
    add(data::chooseField(file, "", data::elevationVariableNames()), "field");
  } catch (const InputError&) {
    for (const data::FieldSummary& f : file.fields()) add(f.name, "field");
  }
  return out;
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace

Run addInfoCommand(CLI::App& parent) {
  auto opts = std::make_shared<InfoOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "info", "describe a NetCDF or GRIB data file: variables, grid, time steps, value ranges");
  cmd->add_option("file", opts->spec, "FILE[:VAR] or FILE[:U,V] (as for --wind-layer)")->required();
  cmd->add_flag("--json", opts->json, "print a JSON object instead of text");
  return [opts]() {
    const data::LayerSpec spec = data::parseLayerSpec(opts->spec);
    const auto file = data::openGridFile(spec.file);
    std::vector<VariableReport> variables = chooseVariables(*file, spec.variables);
    const data::FieldDescription first = file->describe(variables.front().summary.name);
    const data::LatLonGrid& g = first.geometry;

    // Value ranges over every time step, one step in memory at a time.
    for (VariableReport& v : variables) {
      const data::FieldDescription d = file->describe(v.summary.name);
      for (std::size_t step = 0; step < d.steps(); ++step) {
        const data::LatLonGrid grid = file->read(v.summary.name, step);
        v.cells += grid.values.size();
        for (float x : grid.values) {
          if (std::isnan(x)) continue;
          const auto value = static_cast<double>(x);
          v.min = std::min(v.min, value);
          v.max = std::max(v.max, value);
          v.sum += value;
          ++v.valid;
        }
      }
    }
    const bool wind = variables.front().role == "u";
    const double lonLast = g.lon0Deg + (g.width - 1) * g.dLonDeg;
    const double latLast = g.lat0Deg + (g.height - 1) * g.dLatDeg;

    if (opts->json) {
      nlohmann::ordered_json j;
      j["file"] = file->label();
      j["format"] = file->format();
      j["kind"] = wind ? "wind" : "field";
      j["grid"] = {{"width", g.width},
                   {"height", g.height},
                   {"lon_first_deg", g.lon0Deg},
                   {"lon_last_deg", lonLast},
                   {"lat_first_deg", g.lat0Deg},
                   {"lat_last_deg", latLast},
                   {"dlon_deg", g.dLonDeg},
                   {"dlat_deg", g.dLatDeg},
                   {"wraps_longitude", g.wrapsLongitude},
                   {"covers_poles", g.coversPoles()}};
      nlohmann::ordered_json times = nlohmann::ordered_json::array();
      for (const UtcTime& t : first.times) times.push_back(t.toIso8601());
      j["time"] = {{"axis", first.timeAxisName}, {"steps", first.steps()}, {"values", times},
                   {"climatology", first.climatology}};
      nlohmann::ordered_json vars = nlohmann::ordered_json::array();
      for (const VariableReport& v : variables) {
        nlohmann::ordered_json o = {{"name", v.summary.name},
                                    {"role", v.role},
                                    {"standard_name", v.summary.standardName},
                                    {"long_name", v.summary.longName},
                                    {"units", v.summary.units},
                                    {"min", v.min},
                                    {"max", v.max},
                                    {"mean", v.sum / static_cast<double>(v.valid)},
                                    {"valid", v.valid},
                                    {"cells", v.cells}};
        vars.push_back(std::move(o));
      }
      j["variables"] = std::move(vars);
      std::cout << j.dump(2) << '\n';
      return static_cast<int>(kExitOk);
    }

    std::ostringstream out;
    out << "file        " << file->label() << " (" << file->format() << ")\n";
    out << "variables   ";
    if (wind)
      out << "wind: u = " << variables[0].summary.name << ", v = " << variables[1].summary.name;
    else
      for (std::size_t i = 0; i < variables.size(); ++i)
        out << (i ? ", " : "") << variables[i].summary.name;
    out << "\n";
    out << "grid        " << g.width << " x " << g.height << " cells, " << number(g.dLonDeg)
        << " x " << number(g.dLatDeg) << " deg"
        << (g.wrapsLongitude ? ", global in longitude" : ", regional") << "\n";
    out << "longitude   " << number(g.lon0Deg) << " .. " << number(lonLast)
        << " deg east (cell centres)\n";
    out << "latitude    " << number(g.lat0Deg) << " .. " << number(latLast)
        << " deg north (cell centres)\n";
    if (first.times.empty()) {
      out << "time        none (one field)\n";
    } else {
      out << "time        " << first.times.size() << " step" << (first.times.size() == 1 ? "" : "s")
          << " on '" << first.timeAxisName << "': " << first.times.front().toIso8601();
      if (first.times.size() > 1) out << " .. " << first.times.back().toIso8601();
      // A climatology's steps are positions in any year (shown in year 2001).
      if (first.climatology) out << " (climatology: repeats every year)";
      out << "\n";
      constexpr std::size_t kListed = 8;
      if (first.times.size() > 1) {
        out << "            ";
        for (std::size_t i = 0; i < first.times.size(); ++i) {
          if (i == kListed / 2 && first.times.size() > kListed) {
            out << "... ";
            i = first.times.size() - kListed / 2;
          }
          out << first.times[i].toIso8601() << (i + 1 < first.times.size() ? " " : "");
        }
        out << "\n";
      }
    }
    for (const VariableReport& v : variables) {
      out << (v.role == "field" ? "field" : v.role) << std::string(v.role == "field" ? 7 : 11, ' ')
          << v.summary.name;
      if (!v.summary.longName.empty()) out << " \"" << v.summary.longName << "\"";
      if (!v.summary.standardName.empty()) out << " (" << v.summary.standardName << ")";
      out << " [" << (v.summary.units.empty() ? "no units" : v.summary.units) << "]: min "
          << number(v.min) << ", max " << number(v.max) << ", mean "
          << number(v.sum / static_cast<double>(v.valid)) << "; " << (v.cells - v.valid)
          << " of " << v.cells << " values missing\n";
    }
    std::cout << out.str();
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
