#pragma once
// The GDAL side of data/GeoRaster.hpp: implemented in the module oceanglobe-gdal.so
// (data/GeoRasterGdal.cpp), which the program loads the first time it reads a raster through
// GDAL (core/Plugin.hpp), so that a start reading none does not load GDAL's ~65 libraries.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "data/GeoRaster.hpp"

namespace og::data {

/// The module's name (core/Plugin.hpp: oceanglobe-gdal.so beside the executable).
inline constexpr const char* kGdalModule = "oceanglobe-gdal";

/// An open georeferenced colour raster: GeoImageReader's body.
class GeoImageSource {
 public:
  virtual ~GeoImageSource() = default;
  [[nodiscard]] virtual const GeoFootprint& footprint() const = 0;
  [[nodiscard]] virtual const std::string& label() const = 0;
  [[nodiscard]] virtual GeoImage read(double westDeg, double southDeg, double eastDeg, double northDeg, int widthPx,
                                      int heightPx) const = 0;
  [[nodiscard]] virtual GeoImage readWhole(const GeoImageRequest& request) const = 0;
};

/// data/GeoRaster.hpp's readers as the module implements them (each as documented there).
/// Its one object lives as long as the process; every method is thread-safe.
class GeoRasterBackend {
 public:
  virtual ~GeoRasterBackend() = default;
  /// GeoImageReader's constructor.
  [[nodiscard]] virtual std::unique_ptr<GeoImageSource> open(const std::string& path,
                                                             const std::string& label) const = 0;
  [[nodiscard]] virtual GeoImage readImageMemory(std::string_view bytes, std::string_view worldFile,
                                                 const std::string& extension, const std::string& label,
                                                 const GeoImageRequest& request) const = 0;
  [[nodiscard]] virtual LatLonGrid readGrid(const std::filesystem::path& file, int maxSizePx) const = 0;
  [[nodiscard]] virtual ByteRaster readBytes(const std::filesystem::path& file) const = 0;
  [[nodiscard]] virtual ByteRaster readBytesMemory(std::string_view bytes, std::string_view worldFile,
                                                   const std::string& extension, const std::string& label) const = 0;
};

}  // namespace og::data
