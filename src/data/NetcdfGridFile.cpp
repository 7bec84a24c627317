// A NetCDF file as fields on lat/lon grids (GridFile): axes, fill values, packing, time steps.
#include "data/NetcdfFile.hpp"

#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <utility>

#include "core/Error.hpp"
#include "data/NetcdfInternal.hpp"
#include "data/GridLayout.hpp"
#include "data/TimeAxis.hpp"


namespace og::data::detail {
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Field reader

namespace {
std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}


struct Variable {
  int id = -1;
  std::string name;
  nc_type type = NC_NAT;
  std::vector<int> dims;
};

std::string typeName(const NetcdfFile& file, nc_type type) {
  std::array<char, NC_MAX_NAME + 1> name{};
  if (nc_inq_type(file.id(), type, name.data(), nullptr) != NC_NOERR) return "unknown";
  return name.data();
}

std::string dimensionName(const NetcdfFile& file, int dim) {
  std::array<char, NC_MAX_NAME + 1> name{};
  file.check(nc_inq_dimname(file.id(), dim, name.data()), "cannot read a dimension name");
  return name.data();
}

std::size_t dimensionLength(const NetcdfFile& file, int dim) {
  std::size_t length = 0;
  file.check(nc_inq_dimlen(file.id(), dim, &length), "cannot read a dimension length");
  return length;
}

std::vector<Variable> listVariables(const NetcdfFile& file) {
  int count = 0;
  file.check(nc_inq_nvars(file.id(), &count), "cannot list variables");
  std::vector<Variable> variables;
  variables.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int v = 0; v < count; ++v) {
    std::array<char, NC_MAX_NAME + 1> name{};
    std::array<int, NC_MAX_VAR_DIMS> dims{};
    Variable variable;
    int ndims = 0;
    file.check(nc_inq_var(file.id(), v, name.data(), &variable.type, &ndims, dims.data(), nullptr),
               "cannot inspect variable " + std::to_string(v));
    variable.id = v;
    variable.name = name.data();
    variable.dims.assign(dims.begin(), dims.begin() + ndims);
    variables.push_back(std::move(variable));
  }
  return variables;
}

enum class AxisKind { None, Latitude, Longitude };

/// CF: units degrees_north (and spellings) or standard_name latitude; same for longitude.
AxisKind axisKind(const NetcdfFile& file, const Variable& variable) {
  if (variable.dims.size() != 1) return AxisKind::None;
  const std::string units = lower(file.textAttribute(variable.id, "units").value_or(""));
  const std::string standard = lower(file.textAttribute(variable.id, "standard_name").value_or(""));
  const auto oneOf = [](const std::string& s, std::initializer_list<const char*> options) {
    return std::any_of(options.begin(), options.end(), [&](const char* o) { return s == o; });
  };
  if (oneOf(units,
            {"degrees_north", "degree_north", "degrees_n", "degree_n", "degreesn", "degreen"}) ||
      standard == "latitude")
    return AxisKind::Latitude;
  if (oneOf(units,
            {"degrees_east", "degree_east", "degrees_e", "degree_e", "degreese", "degreee"}) ||
      standard == "longitude")
    return AxisKind::Longitude;
  return AxisKind::None;
}

/// The axis variable on each dimension; a coordinate variable (named like its dimension) wins.
using AxisByDimension = std::map<int, const Variable*>;

void addAxis(const NetcdfFile& file, AxisByDimension& axes, const Variable& variable) {
  const int dim = variable.dims[0];
  auto [it, inserted] = axes.emplace(dim, &variable);
  if (!inserted && variable.name == dimensionName(file, dim)) it->second = &variable;
}

std::vector<double> readAxis(const NetcdfFile& file, const Variable& axis) {
  if (!isNumericType(axis.type))
    file.fail("axis '" + axis.name + "' has type " + typeName(file, axis.type) +
              ", expected numbers");
  std::vector<double> values(dimensionLength(file, axis.dims[0]));
  file.check(nc_get_var_double(file.id(), axis.id, values.data()),
             "cannot read axis '" + axis.name + "'");
  return values;
}

std::string joinNames(const std::vector<const Variable*>& variables) {
  std::string text;
  for (const Variable* v : variables) text += (text.empty() ? "" : ", ") + v->name;
  return text;
}

/// netCDF's default fill for a type: what unwritten parts of a variable read as when it has
/// no _FillValue. Bytes have none in practice (every byte value is used).
std::optional<double> defaultFill(nc_type type) {
  switch (type) {
    case NC_SHORT:
      return -32767.0;
    case NC_USHORT:
      return 65535.0;
    case NC_INT:
      return -2147483647.0;
    case NC_UINT:
      return 4294967295.0;
    case NC_INT64:
      return -9223372036854775806.0;
    case NC_UINT64:
      return 18446744073709551614.0;
    case NC_FLOAT:
      return static_cast<double>(9.9692099683868690e+36f);
    case NC_DOUBLE:
      return 9.9692099683868690e+36;
    default:
      return std::nullopt;
  }
}

/// Values that mean "no data". Packed ones compare to the stored number; unpacked ones (a
/// float missing_value on a packed integer field) compare to the unpacked value.
struct FillValues {
  std::vector<double> packed;
  std::vector<double> unpacked;
  double unpackedTolerance = 0.0;

  [[nodiscard]] bool matches(double raw, double value) const {
    for (double f : packed)
      if (raw == f || std::abs(raw - f) <= 1e-6 * std::abs(f)) return true;
    for (double f : unpacked)
      if (std::abs(value - f) <= unpackedTolerance + 1e-6 * std::abs(f)) return true;
    return false;
  }
};

bool isIntegerType(nc_type type) {
  return isNumericType(type) && type != NC_FLOAT && type != NC_DOUBLE;
}
bool isFloatType(nc_type type) { return type == NC_FLOAT || type == NC_DOUBLE; }

bool onAxes(const Variable& v, const AxisByDimension& first, const AxisByDimension& second) {
  const std::size_t n = v.dims.size();
  return n >= 2 && first.count(v.dims[n - 2]) != 0 && second.count(v.dims[n - 1]) != 0;
}

/// Axes found at most this long are refused before reading them (time steps).
constexpr std::size_t kMaxTimeSteps = 1'000'000;

/// Everything needed to read one field, validated.
struct FieldPlan {
  const Variable* field = nullptr;
  FieldDescription description;
  GridLayout layout;
  std::size_t nLat = 0;
  std::size_t nLon = 0;
  int timeDim = -1;  ///< index into field->dims of the time dimension, -1 if none
  double scale = 1.0;
  double offset = 0.0;
  FillValues fills;
};

/// A NetCDF dataset as a GridFile.
class NetcdfGridFile final : public GridFile {
 public:
  explicit NetcdfGridFile(NetcdfFile file) : nc_(std::move(file)), variables_(listVariables(nc_)) {
    for (const Variable& v : variables_) {
      const AxisKind kind = axisKind(nc_, v);
      if (kind == AxisKind::Latitude) addAxis(nc_, latAxes_, v);
      if (kind == AxisKind::Longitude) addAxis(nc_, lonAxes_, v);
    }
  }

  [[nodiscard]] const std::string& label() const override { return nc_.label(); }

  [[nodiscard]] std::string format() const override {
    int format = 0;
    if (nc_inq_format(nc_.id(), &format) != NC_NOERR) return "NetCDF";
    switch (format) {
      case NC_FORMAT_CLASSIC:
        return "NetCDF classic";
      case NC_FORMAT_64BIT_OFFSET:
        return "NetCDF 64-bit offset";
      case NC_FORMAT_CDF5:
        return "NetCDF CDF5";
      case NC_FORMAT_NETCDF4_CLASSIC:
        return "NetCDF-4 classic model";
      default:
        return "NetCDF-4";
    }
  }

  [[nodiscard]] std::vector<FieldSummary> fields() const override {
    requireAxes();
    std::vector<FieldSummary> out;
    for (const Variable& v : variables_)
      if (onAxes(v, latAxes_, lonAxes_)) out.push_back(summarise(v));
    if (out.empty()) {
      for (const Variable& v : variables_)
        if (onAxes(v, lonAxes_, latAxes_))
          nc_.fail("variable '" + v.name +
                   "' is stored as (longitude, latitude); only (latitude, longitude) is supported");
      nc_.fail("no field on (latitude, longitude) axes");
    }
    return out;
  }

  [[nodiscard]] FieldDescription describe(const std::string& name) const override {
    return plan(name).description;
  }

  [[nodiscard]] LatLonGrid read(const std::string& name, std::size_t step) const override;

 private:
  void requireAxes() const {
    if (latAxes_.empty())
      nc_.fail(
          "no latitude axis (a 1-D variable with units degrees_north or standard_name "
          "latitude)");
    if (lonAxes_.empty())
      nc_.fail(
          "no longitude axis (a 1-D variable with units degrees_east or standard_name "
          "longitude)");
  }

  [[nodiscard]] FieldSummary summarise(const Variable& v) const {
    FieldSummary s;
    s.name = v.name;
    s.standardName = nc_.textAttribute(v.id, "standard_name").value_or("");
    s.longName = nc_.textAttribute(v.id, "long_name").value_or("");
    s.units = nc_.textAttribute(v.id, "units").value_or("");
    return s;
  }

  [[nodiscard]] const Variable* coordinateOf(int dim) const {
    const std::string name = dimensionName(nc_, dim);
    for (const Variable& v : variables_)
      if (v.name == name && v.dims.size() == 1 && v.dims[0] == dim) return &v;
    return nullptr;
  }

  /// Finds the time dimension among the leading ones; others must hold one step.
  void planLeadingDimensions(FieldPlan& p) const;
  [[nodiscard]] FieldPlan plan(const std::string& name) const;

  NetcdfFile nc_;
  std::vector<Variable> variables_;  // never resized after construction: the maps point into it
  AxisByDimension latAxes_;
  AxisByDimension lonAxes_;
};

void NetcdfGridFile::planLeadingDimensions(FieldPlan& p) const {
  const Variable& field = *p.field;
  const std::string quoted = "variable '" + field.name + "'";
  const std::size_t rank = field.dims.size();
  for (std::size_t d = 0; d + 2 < rank; ++d) {
    const int dim = field.dims[d];
    const std::size_t length = dimensionLength(nc_, dim);
    const std::string dimName = dimensionName(nc_, dim);
    const Variable* coordinate = coordinateOf(dim);
    std::optional<TimeUnits> units;
    std::string calendar;
    std::string unitsText;
    if (coordinate != nullptr && isNumericType(coordinate->type)) {
      unitsText = nc_.textAttribute(coordinate->id, "units").value_or("");
      units = parseTimeUnits(unitsText);
      calendar = nc_.textAttribute(coordinate->id, "calendar").value_or("");
    }
    const bool looksLikeTime = units.has_value() || lower(dimName).find("time") != std::string::npos ||
                               lower(unitsText).find(" since ") != std::string::npos;
    if (length == 0) nc_.fail(quoted + " has no steps along '" + dimName + "'");
    if (length == 1 && !units) continue;  // a single level/ensemble member/untimed step
    if (length > 1 && !looksLikeTime)
      nc_.fail(quoted + " has " + std::to_string(length) + " steps along '" + dimName +
               "'; only one 2-D field per time step is supported");
    if (p.timeDim >= 0)
      nc_.fail(quoted + " has two time axes ('" + dimensionName(nc_, field.dims[static_cast<std::size_t>(p.timeDim)]) +
               "' and '" + dimName + "')");
    if (length > 1 && coordinate == nullptr)
      nc_.fail(quoted + " has " + std::to_string(length) + " steps along '" + dimName +
               "' but no time coordinate variable '" + dimName + "' to tell them apart");
    if (length > kMaxTimeSteps)
      nc_.fail("time axis '" + dimName + "' has " + std::to_string(length) + " steps (limit " +
               std::to_string(kMaxTimeSteps) + ")");
    std::vector<double> values(length);
    nc_.check(nc_get_var_double(nc_.id(), coordinate->id, values.data()),
              "cannot read time axis '" + dimName + "'");
    p.timeDim = static_cast<int>(d);
    p.description.timeAxisName = dimName;
    // Calendars, climatologies (CF `climatology`, Ferret `modulo`) and unit errors: TimeAxis.
    const bool climatology = nc_.textAttribute(coordinate->id, "climatology").has_value() ||
                             nc_.textAttribute(coordinate->id, "modulo").has_value();
    AxisTimes axis = decodeTimeAxis(nc_.label(), dimName, values, unitsText, calendar, climatology);
    p.description.times = std::move(axis.times);
    p.description.climatology = axis.climatology;
  }
}

FieldPlan NetcdfGridFile::plan(const std::string& name) const {
  requireAxes();
  const auto found = std::find_if(variables_.begin(), variables_.end(),
                                  [&](const Variable& v) { return v.name == name; });
  if (found == variables_.end()) {
    std::vector<const Variable*> candidates;
    for (const Variable& v : variables_)
      if (onAxes(v, latAxes_, lonAxes_)) candidates.push_back(&v);
    nc_.fail("no variable '" + name + "'" +
             (candidates.empty()
                  ? std::string()
                  : " (fields on latitude/longitude: " + joinNames(candidates) + ")"));
  }
  const Variable& field = *found;
  const std::string quoted = "variable '" + field.name + "'";
  if (onAxes(field, lonAxes_, latAxes_) && !onAxes(field, latAxes_, lonAxes_))
    nc_.fail(quoted + " is stored as (longitude, latitude); only (latitude, longitude) is supported");
  if (!onAxes(field, latAxes_, lonAxes_))
    nc_.fail(quoted + " is not a field on (latitude, longitude) axes");
  if (!isNumericType(field.type))
    nc_.fail(quoted + " has type " + typeName(nc_, field.type) + ", expected numbers");

  FieldPlan p;
  p.field = &field;
  p.description.summary = summarise(field);
  planLeadingDimensions(p);

  const std::size_t rank = field.dims.size();
  const Variable& latAxis = *latAxes_.at(field.dims[rank - 2]);
  const Variable& lonAxis = *lonAxes_.at(field.dims[rank - 1]);
  p.nLat = dimensionLength(nc_, field.dims[rank - 2]);
  p.nLon = dimensionLength(nc_, field.dims[rank - 1]);
  checkGridShape(nc_.label(), p.nLat, p.nLon);  // before reading anything sized by them
  const std::vector<double> lat = readAxis(nc_, latAxis);
  const std::vector<double> lon = readAxis(nc_, lonAxis);
  p.layout = planGridLayout(nc_.label(), lat, latAxis.name, latAxis.type == NC_FLOAT, lon,
                            lonAxis.name, lonAxis.type == NC_FLOAT);

  // Packing: value = raw * scale_factor + add_offset.
  if (const auto a = nc_.numericAttribute(field.id, "scale_factor")) p.scale = a->values[0];
  if (const auto a = nc_.numericAttribute(field.id, "add_offset")) p.offset = a->values[0];
  if (!std::isfinite(p.scale) || !std::isfinite(p.offset) || p.scale == 0.0)
    nc_.fail(quoted + " has an unusable scale_factor/add_offset");
  const bool packed = p.scale != 1.0 || p.offset != 0.0;

  p.fills.unpackedTolerance = 0.5 * std::abs(p.scale);
  if (const auto a = nc_.numericAttribute(field.id, "_FillValue")) {
    p.fills.packed.push_back(a->values[0]);
  } else if (const auto d = defaultFill(field.type)) {
    p.fills.packed.push_back(*d);
  }
  if (const auto a = nc_.numericAttribute(field.id, "missing_value")) {
    // A float missing_value on a packed integer field is in unpacked units (common practice,
    // though CF asks for packed units).
    const bool unpackedUnits =
        packed && isIntegerType(field.type) && isFloatType(static_cast<nc_type>(a->type));
    for (double m : a->values) (unpackedUnits ? p.fills.unpacked : p.fills.packed).push_back(m);
  }

  LatLonGrid& g = p.description.geometry;
  g.name = field.name;
  g.units = p.description.summary.units;
  g.width = p.layout.width;
  g.height = p.layout.height;
  g.lon0Deg = p.layout.lon0Deg;
  g.lat0Deg = p.layout.lat0Deg;
  g.dLonDeg = p.layout.dLonDeg;
  g.dLatDeg = p.layout.dLatDeg;
  g.wrapsLongitude = p.layout.wrapsLongitude;
  return p;
}

LatLonGrid NetcdfGridFile::read(const std::string& name, std::size_t step) const {
  const FieldPlan p = plan(name);
  const std::string quoted = "variable '" + p.field->name + "'";
  if (step >= p.description.steps())
    nc_.fail(quoted + " has no time step " + std::to_string(step));
  LatLonGrid grid = p.description.geometry;
  const std::size_t nLat = p.nLat;
  const std::size_t nLon = p.nLon;
  const auto width = static_cast<std::size_t>(p.layout.width);
  grid.values.assign(nLat * width, std::numeric_limits<float>::quiet_NaN());

  // Read whole rows in blocks of about a million values: bounded extra memory, and doubles
  // keep 32-bit integers and fill comparisons exact.
  const std::size_t rank = p.field->dims.size();
  const std::size_t rowsPerBlock = std::max<std::size_t>(1, (std::size_t{1} << 20) / nLon);
  std::vector<double> block(std::min(rowsPerBlock, nLat) * nLon);
  std::vector<std::size_t> start(rank, 0);
  std::vector<std::size_t> count(rank, 1);
  if (p.timeDim >= 0) start[static_cast<std::size_t>(p.timeDim)] = step;
  std::size_t valid = 0;
  constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());
  for (std::size_t row0 = 0; row0 < nLat; row0 += rowsPerBlock) {
    const std::size_t rows = std::min(rowsPerBlock, nLat - row0);
    start[rank - 2] = row0;
    count[rank - 2] = rows;
    count[rank - 1] = nLon;
    nc_.check(nc_get_vara_double(nc_.id(), p.field->id, start.data(), count.data(), block.data()),
              "cannot read " + quoted);
    for (std::size_t r = 0; r < rows; ++r) {
      float* out = grid.values.data() + p.layout.outputRow(row0 + r) * width;
      const double* in = block.data() + r * nLon;
      for (std::size_t c = 0; c < width; ++c) {
        const double raw = in[p.layout.fileColumn(c, nLon)];
        if (std::isnan(raw)) continue;
        const double value = raw * p.scale + p.offset;
        if (p.fills.matches(raw, value)) continue;
        if (!std::isfinite(value) || std::abs(value) > kFloatMax)
          nc_.fail(quoted + " has a non-finite or out-of-range value " + std::to_string(value) +
                   " at latitude index " + std::to_string(row0 + r) + ", longitude index " +
                   std::to_string(p.layout.fileColumn(c, nLon)));
        out[c] = static_cast<float>(value);
        ++valid;
      }
    }
  }
  if (valid == 0)
    nc_.fail(quoted + " holds no data" +
             (p.description.times.size() > 1 ? " at time step " + std::to_string(step) : "") +
             " (every value is fill/missing)");
  return grid;
}

}  // namespace

std::unique_ptr<GridFile> openNetcdf(NetcdfFile file) {
  return std::make_unique<NetcdfGridFile>(std::move(file));
}

}  // namespace og::data::detail
