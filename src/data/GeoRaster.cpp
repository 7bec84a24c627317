// data/GeoRaster.hpp's readers: GDAL's side lives in the module oceanglobe-gdal.so
// (data/GeoRasterGdal.cpp), loaded with the first read (core/Plugin.hpp).
#include "data/GeoRaster.hpp"

#include <array>
#include <cctype>
#include <fstream>
#include <initializer_list>
#include <system_error>

#include "core/Plugin.hpp"
#include "data/GeoRasterBackend.hpp"

namespace og::data {
namespace fs = std::filesystem;

namespace {

const GeoRasterBackend& gdal() {
  return *static_cast<const GeoRasterBackend*>(plugin::load(kGdalModule, "reading GeoTIFF and other GDAL rasters"));
}

bool hasExtension(const fs::path& file, std::initializer_list<const char*> exts) {
  std::string e = file.extension().string();
  for (char& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const char* x : exts)
    if (e == x) return true;
  return false;
}

}  // namespace

GeoImageReader::GeoImageReader(const std::string& path, const std::string& label) : source_(gdal().open(path, label)) {}
GeoImageReader::~GeoImageReader() = default;

const GeoFootprint& GeoImageReader::footprint() const { return source_->footprint(); }
const std::string& GeoImageReader::label() const { return source_->label(); }

GeoImage GeoImageReader::read(double westDeg, double southDeg, double eastDeg, double northDeg, int widthPx,
                              int heightPx) const {
  return source_->read(westDeg, southDeg, eastDeg, northDeg, widthPx, heightPx);
}

GeoImage GeoImageReader::readWhole(const GeoImageRequest& request) const { return source_->readWhole(request); }

GeoImage readGeoImage(const fs::path& file, const GeoImageRequest& request) {
  GeoImage img = GeoImageReader(file.string(), file.string()).readWhole(request);
  img.sourcePath = file.string();
  return img;
}

GeoImage readGeoImageMemory(std::string_view bytes, std::string_view worldFile, const std::string& extension,
                            const std::string& label, const GeoImageRequest& request) {
  return gdal().readImageMemory(bytes, worldFile, extension, label, request);
}

LatLonGrid readGeoRasterGrid(const fs::path& file, int maxSizePx) { return gdal().readGrid(file, maxSizePx); }

ByteRaster readGeographicBytes(const fs::path& file) { return gdal().readBytes(file); }

ByteRaster readGeographicBytesMemory(std::string_view bytes, std::string_view worldFile,
                                     const std::string& extension, const std::string& label) {
  return gdal().readBytesMemory(bytes, worldFile, extension, label);
}

bool isGdalRasterFile(const fs::path& file) {
  std::array<unsigned char, 4> head{};
  std::error_code ec;
  if (fs::is_regular_file(file, ec)) {
    std::ifstream in(file, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), head.size());
    const bool tiff = (head[0] == 'I' && head[1] == 'I' && (head[2] == 42 || head[2] == 43) && head[3] == 0) ||
                      (head[0] == 'M' && head[1] == 'M' && head[2] == 0 && (head[3] == 42 || head[3] == 43));
    if (in.gcount() == 4 && tiff) return true;
  }
  return hasExtension(file, {".tif", ".tiff", ".vrt", ".hgt", ".asc", ".img", ".dt0", ".dt1", ".dt2",
                             ".dem", ".bil", ".jp2"});
}

}  // namespace og::data
