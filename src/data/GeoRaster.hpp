#pragma once
// Georeferenced rasters through GDAL: imagery (GeoTIFF/COG, JPEG/PNG with a world file, and
// anything else GDAL reads) reprojected with GDAL/PROJ to geographic latitude/longitude
// (EPSG:4326), and single-band rasters (GeoTIFF DEMs) as LatLonGrids. GDAL's own messages are
// captured by a scoped error handler; every failure is an og::InputError "FILE: problem".
// GDAL itself is loaded with the first read (data/GeoRasterBackend.hpp, core/Plugin.hpp): every
// reader here throws og::InternalError when its module cannot be loaded.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "data/LatLonGrid.hpp"

namespace og::data {

/// An RGBA image on a regular latitude/longitude grid (EPSG:4326).
struct GeoImage {
  std::string label;      ///< the file (or memory label) it came from
  int width = 0;          ///< columns, west to east
  int height = 0;         ///< rows, south to north (row 0 is the southernmost)
  double westDeg = 0.0;   ///< outer edges of the image, degrees (west < east, south < north)
  double southDeg = 0.0;
  double eastDeg = 0.0;
  double northDeg = 0.0;
  /// width * height * 4 bytes: sRGB-encoded colour as in the file, alpha = coverage
  /// (0 where the source has no data or lies outside its footprint).
  std::vector<std::uint8_t> rgba;
  /// The file it was read from, for reading finer windows of it later (imagery tiles); empty
  /// for an image in memory.
  std::string sourcePath;

  [[nodiscard]] bool coversGlobe() const { return eastDeg - westDeg >= 359.9 && northDeg - southDeg >= 179.9; }
  /// The pixel at (column, row), row 0 south. Channel c in [0, 4).
  [[nodiscard]] std::uint8_t at(int column, int row, int c) const {
    return rgba[(static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(column)) * 4 + static_cast<std::size_t>(c)];
  }
};

/// How a raster is resampled onto the latitude/longitude grid.
struct GeoImageRequest {
  /// The longest side of the result, pixels, in [16, 16384]: larger sources are averaged down.
  int maxSizePx = 2048;
  /// Exactly maxSizePx × maxSizePx pixels whatever the source's size (texture arrays).
  bool square = false;
};

/// Reads a georeferenced raster (1 band grey, 3 bands RGB, 4 bands RGBA, or paletted; 8-bit, or
/// wider integers/floats scaled from their range to 0..255) in any coordinate system PROJ can
/// transform to EPSG:4326 (EPSG:4326 and Web Mercator EPSG:3857 are the common ones; UTM works
/// too). A geotransform without a coordinate system (a bare world file) is taken as EPSG:4326
/// when its extent lies within ±180°/±90°. Throws og::InputError "FILE: problem" when GDAL
/// cannot read it, when it has no georeferencing, or when it cannot be reprojected.
GeoImage readGeoImage(const std::filesystem::path& file, const GeoImageRequest& request = {});

/// The footprint of a raster in EPSG:4326, degrees, and its size there at its own resolution.
struct GeoFootprint {
  double westDeg = 0.0, southDeg = 0.0, eastDeg = 0.0, northDeg = 0.0;
  int widthPx = 0, heightPx = 0;  ///< GDAL's suggested size that keeps the source's resolution
  /// The source's finest cell in EPSG:4326, degrees (the smaller of its two sides).
  [[nodiscard]] double cellDeg() const {
    const double w = (eastDeg - westDeg) / widthPx, h = (northDeg - southDeg) / heightPx;
    return w < h ? w : h;
  }
};

class GeoImageSource;  // data/GeoRasterBackend.hpp

/// An open georeferenced colour raster from which windows are read again and again (imagery
/// tiles), each resampled with GDAL's warper (which uses the file's overviews when reading
/// coarser than the source). One thread at a time per reader: open one per thread.
class GeoImageReader {
 public:
  /// Opens `path` (a file or a /vsimem/ path), named `label` in messages, as readGeoImage
  /// reads it. Throws og::InputError "LABEL: problem".
  GeoImageReader(const std::string& path, const std::string& label);
  ~GeoImageReader();
  GeoImageReader(const GeoImageReader&) = delete;
  GeoImageReader& operator=(const GeoImageReader&) = delete;

  [[nodiscard]] const GeoFootprint& footprint() const;
  [[nodiscard]] const std::string& label() const;
  /// The window west..east × south..north (degrees; it may reach past the footprint, where
  /// alpha is 0) resampled to widthPx × heightPx. Throws og::InputError "LABEL: problem" when
  /// the pixels cannot be read (a truncated or corrupt file).
  GeoImage read(double westDeg, double southDeg, double eastDeg, double northDeg, int widthPx,
                int heightPx) const;
  /// The whole footprint as readGeoImage returns it.
  [[nodiscard]] GeoImage readWhole(const GeoImageRequest& request) const;

 private:
  std::unique_ptr<GeoImageSource> source_;
};

/// Same for an image in memory (e.g. embedded in the binary) with its world file's text
/// (`worldFile`, may be empty when the format carries its own georeferencing); `extension`
/// ("jpg", "png", "tif") tells GDAL the format, `label` names it in messages.
GeoImage readGeoImageMemory(std::string_view bytes, std::string_view worldFile,
                            const std::string& extension, const std::string& label,
                            const GeoImageRequest& request = {});

/// Reads band 1 of a georeferenced single-field raster (a GeoTIFF DEM: SRTM, Copernicus
/// GLO-30, GEBCO) as a LatLonGrid in the file's units, nodata -> NaN. Rasters in a projected
/// coordinate system are reprojected to EPSG:4326 (bilinear); rasters longer than
/// `maxSizePx` on a side are averaged down to it. Throws og::InputError "FILE: problem".
LatLonGrid readGeoRasterGrid(const std::filesystem::path& file, int maxSizePx = 8192);

/// Band 1 of a north-up raster on a latitude/longitude grid, as bytes, without resampling (for
/// large masks: no reprojection, no RGBA expansion).
struct ByteRaster {
  int width = 0, height = 0;
  double westDeg = 0.0, southDeg = 0.0;  ///< outer edges
  double cellLonDeg = 0.0, cellLatDeg = 0.0;
  std::vector<std::uint8_t> values;  ///< rows south to north
};
/// Reads `file` (or, with `bytes` non-empty, that image in memory with its world file text)
/// as a ByteRaster. Refuses rasters that are not north-up in degrees (geographic or no
/// coordinate system). Throws og::InputError "LABEL: problem".
ByteRaster readGeographicBytes(const std::filesystem::path& file);
ByteRaster readGeographicBytesMemory(std::string_view bytes, std::string_view worldFile,
                                     const std::string& extension, const std::string& label);

/// True when GDAL rather than NetCDF/GRIB should read `file`: TIFF/BigTIFF by its first bytes,
/// or an extension GDAL's raster drivers own (.tif, .tiff, .vrt, .hgt, .asc, .img, .dt2 ...).
bool isGdalRasterFile(const std::filesystem::path& file);

}  // namespace og::data
