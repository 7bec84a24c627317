#pragma once
// A gridded data file (NetCDF or GRIB) seen as a set of fields on regular latitude/longitude
// grids, each with zero or more time steps. Opening validates the container; describe()
// validates one field's axes, shape and time axis without reading its values; read() reads
// one time step and normalises it into a LatLonGrid (rows south->north, NaN = no data).
// Every failure is an og::InputError "LABEL: problem".
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Time.hpp"
#include "data/LatLonGrid.hpp"

namespace og::data {

/// One field on latitude/longitude axes, as the file names it.
struct FieldSummary {
  std::string name;          ///< variable name (NetCDF) or shortName (GRIB), e.g. "u10", "10u"
  std::string standardName;  ///< CF standard_name when present, e.g. "eastward_wind"
  std::string longName;      ///< long_name / GRIB name, for messages and `info`
  std::string units;         ///< as found in the file, e.g. "m s**-1"
};

/// A field's geometry and time axis, validated, without values.
struct FieldDescription {
  FieldSummary summary;
  LatLonGrid geometry;          ///< normalised geometry; `values` is empty
  std::vector<UtcTime> times;   ///< one per step, strictly increasing; empty: one untimed step
  std::string timeAxisName;     ///< e.g. "time", "valid_time"; empty without a time axis
  /// A climatology: the steps repeat every year; `times` are their positions in the year,
  /// placed in year detail::kClimatologyYear, distinct but not necessarily in order.
  bool climatology = false;
  [[nodiscard]] std::size_t steps() const { return times.empty() ? 1 : times.size(); }
};

class GridFile {
 public:
  virtual ~GridFile() = default;
  GridFile() = default;
  GridFile(const GridFile&) = delete;
  GridFile& operator=(const GridFile&) = delete;

  /// The file name (or memory label) used in messages.
  [[nodiscard]] virtual const std::string& label() const = 0;
  /// "NetCDF classic", "NetCDF-4", "GRIB2", ...
  [[nodiscard]] virtual std::string format() const = 0;
  /// Fields on latitude/longitude axes, in file order. Throws when the file has no usable axes.
  [[nodiscard]] virtual std::vector<FieldSummary> fields() const = 0;
  /// Validates field `name` (axes, shape, time axis). Throws "no variable 'X'" and the like.
  [[nodiscard]] virtual FieldDescription describe(const std::string& name) const = 0;
  /// Reads step `step` (< describe(name).steps()) of field `name`, unpacked, fill -> NaN,
  /// in the file's units. Throws if no value is valid or one is non-finite.
  [[nodiscard]] virtual LatLonGrid read(const std::string& name, std::size_t step) const = 0;
};

/// Opens a NetCDF (classic, 64-bit offset, CDF5, NetCDF-4) or GRIB (edition 1 or 2) file,
/// recognised by its first bytes.
std::unique_ptr<GridFile> openGridFile(const std::filesystem::path& file);
/// Same for an in-memory image; the bytes are copied, `label` names it in messages.
std::unique_ptr<GridFile> openGridMemory(std::string_view bytes, const std::string& label);

/// "FILE[:A[,B...]]": a layer's file and the variables the user named (may be empty).
struct LayerSpec {
  std::filesystem::path file;
  std::vector<std::string> variables;
};
/// Splits a layer spec. An existing file whose name contains ':' is taken whole; a suffix
/// after the last ':' that contains '/' is part of the path. Throws InputError on empty names.
LayerSpec parseLayerSpec(const std::string& spec);

/// Which steps of a time axis make up an instant: value = (1 - weight) * first + weight * second.
struct StepChoice {
  std::size_t first = 0;
  std::size_t second = 0;
  double weight = 0.0;  ///< in [0, 1]; 0 when first == second
};
/// No time, or an untimed field: step 0. Before the first or after the last step: that end step
/// (clamped, no extrapolation). Otherwise the two steps around `time`, linearly weighted.
StepChoice chooseSteps(const std::vector<UtcTime>& times, std::optional<UtcTime> time);
/// Same for a field: cyclic through the year end for a climatology (by the position of `time`
/// in its year), else as above.
StepChoice chooseFieldSteps(const FieldDescription& field, std::optional<UtcTime> time);

/// Picks a single field for a scalar layer: `requested` if given, else the only field on
/// latitude/longitude axes, else the first of `preferredNames` present. Throws otherwise.
std::string chooseField(const GridFile& file, const std::string& requested,
                        const std::vector<std::string>& preferredNames);

}  // namespace og::data
