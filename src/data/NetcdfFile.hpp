#pragma once
// Internal to og_data: a NetCDF file opened read-only through netCDF-C (from disk or from
// memory), and its view as a GridFile.
// Every failure is an og::InputError "LABEL: problem".
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "data/GridFile.hpp"

namespace og::data::detail {

/// An open dataset. netCDF-C is not thread-safe, so each NetcdfFile holds a process-wide lock
/// from open to close: datasets are read one at a time, from any thread.
class NetcdfFile {
 public:
  /// Opens a file on disk (classic, 64-bit offset, CDF5 or NetCDF-4/HDF5).
  static NetcdfFile open(const std::filesystem::path& file);
  /// Opens an in-memory image; the bytes are copied, `label` names it in messages.
  static NetcdfFile openMemory(std::string_view bytes, const std::string& label);

  NetcdfFile(NetcdfFile&& other) noexcept;
  NetcdfFile& operator=(NetcdfFile&&) = delete;
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  ~NetcdfFile();

  [[nodiscard]] int id() const { return id_; }
  [[nodiscard]] const std::string& label() const { return label_; }

  /// Throws InputError "LABEL: problem".
  [[noreturn]] void fail(const std::string& problem) const;
  /// Throws unless `status` is NC_NOERR; the message adds netCDF's explanation.
  void check(int status, const std::string& doing) const;

  /// A text attribute (char or string type), trimmed; nullopt when absent or not text.
  /// `varid` may be NC_GLOBAL.
  [[nodiscard]] std::optional<std::string> textAttribute(int varid, const char* name) const;

  struct Numbers {
    int type = 0;                ///< netCDF type of the attribute (nc_type)
    std::vector<double> values;  ///< converted to double, at least one
  };
  /// A numeric attribute; nullopt when absent. Throws when present but not numeric.
  [[nodiscard]] std::optional<Numbers> numericAttribute(int varid, const char* name) const;

 private:
  NetcdfFile(int id, std::string label, std::vector<char> memory,
             std::unique_lock<std::mutex> lock);
  std::unique_lock<std::mutex> lock_;  // declared first: released after the dataset is closed
  int id_ = -1;
  std::string label_;
  std::vector<char> memory_;  // backs an in-memory dataset for as long as it is open
};

/// The dataset as a GridFile (fields on CF latitude/longitude axes, with a time axis).
std::unique_ptr<GridFile> openNetcdf(NetcdfFile file);

}  // namespace og::data::detail
