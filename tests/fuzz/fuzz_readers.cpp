// libFuzzer target for the data readers (NetCDF classic/CDF5 and GRIB from memory): any input
// must either load or raise og::InputError; anything else (a crash, a sanitizer report, another
// exception escaping, a hang) is a bug. Built only with -DOCEANGLOBE_FUZZ=ON; see docs/data.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "data/Elevation.hpp"
#include "data/GridFile.hpp"
#include "data/WindField.hpp"
#include "data/WindLayers.hpp"

namespace {
/// HDF5 (NetCDF-4) images are skipped unless OG_FUZZ_HDF5=1: that parser is libhdf5's, not
/// ours, and it is not built with the sanitizers.
bool fuzzHdf5() {
  static const bool enabled = [] {
    const char* v = std::getenv("OG_FUZZ_HDF5");
    return v != nullptr && v[0] == '1';
  }();
  return enabled;
}

void exercise(std::string_view bytes) {
  const auto file = og::data::openGridMemory(bytes, "fuzz");
  for (const auto& field : file->fields()) {
    const auto d = file->describe(field.name);
    (void)file->read(field.name, d.steps() - 1);
  }
  og::data::WindLayers layers;
  layers.push(og::data::readWind(*file, {}, og::UtcTime{1.7e9}));
  (void)layers.sample(12.0, 34.0);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = [] {
    og::log::setLevel(og::log::Level::Error);
    return true;
  }();
  (void)quiet;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (!fuzzHdf5() && bytes.substr(0, 4) == "\x89HDF") return 0;
  try {
    exercise(bytes);
  } catch (const og::InputError&) {
  }
  try {
    (void)og::data::readElevationMemory(bytes, "fuzz");
  } catch (const og::InputError&) {
  }
  return 0;
}
