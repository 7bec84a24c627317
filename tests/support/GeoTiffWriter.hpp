#pragma once
// Synthetic georeferenced RGB rasters written with GDAL (a GeoTIFF unless another driver is
// named), in geographic degrees (EPSG:4326) or Web Mercator metres (EPSG:3857), for the
// imagery and raster readers' tests (unit tier: data_georaster; GL tier: land_imagery).
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace og::test {

/// A latitude/longitude box, degrees.
struct GeoBox {
  double westDeg = 0.0, eastDeg = 0.0, southDeg = 0.0, northDeg = 0.0;
};

using Rgb8 = std::array<std::uint8_t, 3>;

/// Web Mercator northing of a latitude, m (spherical, the WGS84 semi-major axis).
inline double webMercatorY(double latDeg) {
  constexpr double kPi = 3.14159265358979323846;
  return 6378137.0 * std::log(std::tan(kPi / 4 + latDeg * kPi / 360));
}
/// Latitude of a Web Mercator northing, degrees.
inline double webMercatorLat(double yM) {
  constexpr double kPi = 3.14159265358979323846;
  return (2 * std::atan(std::exp(yM / 6378137.0)) - kPi / 2) * 180 / kPi;
}

/// Writes `file`: widthPx x heightPx pixels covering `box` in `epsg` (4326 or 3857), north up;
/// each pixel the colour `colourAt(latDeg, lonDeg)` of its centre. Throws std::runtime_error
/// when GDAL fails.
inline std::filesystem::path writeGeoRaster(const std::filesystem::path& file, int epsg, int widthPx,
                                            int heightPx, const GeoBox& box,
                                            const std::function<Rgb8(double, double)>& colourAt,
                                            const std::string& driver = "GTiff") {
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName(driver.c_str()), file.c_str(), widthPx, heightPx, 3,
                               GDT_Byte, nullptr);
  if (ds == nullptr) throw std::runtime_error(file.string() + ": GDAL cannot create it");
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  const bool degrees = epsg == 4326;
  const double metresPerDeg = 6378137.0 * 3.14159265358979323846 / 180.0;
  const double x0 = degrees ? box.westDeg : box.westDeg * metresPerDeg;
  const double x1 = degrees ? box.eastDeg : box.eastDeg * metresPerDeg;
  const double y0 = degrees ? box.southDeg : webMercatorY(box.southDeg);
  const double y1 = degrees ? box.northDeg : webMercatorY(box.northDeg);
  std::array<double, 6> gt{x0, (x1 - x0) / widthPx, 0, y1, 0, -(y1 - y0) / heightPx};
  GDALSetGeoTransform(ds, gt.data());
  std::vector<std::array<std::uint8_t, 3>> colours(static_cast<std::size_t>(widthPx * heightPx));
  for (int r = 0; r < heightPx; ++r)
    for (int c = 0; c < widthPx; ++c) {
      const double y = y1 + (r + 0.5) * gt[5];
      const double lat = degrees ? y : webMercatorLat(y);
      const double lon = box.westDeg + (c + 0.5) * (box.eastDeg - box.westDeg) / widthPx;
      colours[static_cast<std::size_t>(r * widthPx + c)] = colourAt(lat, lon);
    }
  for (int b = 0; b < 3; ++b) {
    std::vector<std::uint8_t> px(colours.size());
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = colours[i][static_cast<std::size_t>(b)];
    if (GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Write, 0, 0, widthPx, heightPx, px.data(), widthPx,
                     heightPx, GDT_Byte, 0, 0) != CE_None) {
      GDALClose(ds);
      throw std::runtime_error(file.string() + ": GDAL cannot write band " + std::to_string(b + 1));
    }
  }
  GDALClose(ds);
  return file;
}

}  // namespace og::test
