// oceanglobe-gdal.so: data/GeoRaster.hpp's readers through GDAL (data/GeoRasterBackend.hpp),
// loaded by the program when it first reads such a raster (core/Plugin.hpp).
#include "data/GeoRasterBackend.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <system_error>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Plugin.hpp"

namespace og::data {
namespace fs = std::filesystem;

namespace {

void registerGdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    // Never look for sidecar files on the network or spend time on .aux.xml statistics files.
    CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");
    CPLSetConfigOption("GDAL_DISABLE_READDIR_ON_OPEN", "NO");
    // A truncated or corrupt JPEG is an error, not a warning with grey pixels.
    CPLSetConfigOption("GDAL_ERROR_ON_LIBJPEG_WARNING", "TRUE");
  });
}

/// Captures GDAL's errors for the duration of a read (thread-local handler stack): the last
/// failure message names the problem in our InputError, warnings go to the debug log.
class GdalErrors {
 public:
  GdalErrors() { CPLPushErrorHandlerEx(&GdalErrors::handle, this); }
  ~GdalErrors() { CPLPopErrorHandler(); }
  GdalErrors(const GdalErrors&) = delete;
  GdalErrors& operator=(const GdalErrors&) = delete;

  /// The last error GDAL reported, or `fallback` when it reported none.
  [[nodiscard]] std::string last(const std::string& fallback) const {
    return message_.empty() ? fallback : message_;
  }

 private:
  static void CPL_STDCALL handle(CPLErr level, CPLErrorNum, const char* message) {
    auto* self = static_cast<GdalErrors*>(CPLGetErrorHandlerUserData());
    if (level >= CE_Failure && self != nullptr && message != nullptr) {
      self->message_ = message;  // one line: our messages are single lines
      std::replace(self->message_.begin(), self->message_.end(), '\n', ' ');
    }
    else if (message != nullptr) log::debug(std::string("GDAL: ") + message);
  }
  std::string message_;
};

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds != nullptr) GDALClose(ds);
  }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

[[noreturn]] void fail(const std::string& label, const std::string& problem) {
  throw InputError(label + ": " + problem);
}

Dataset openRaster(const std::string& path, const std::string& label, const GdalErrors& errors) {
  std::error_code ec;
  if (path.rfind("/vsimem/", 0) != 0 && !fs::is_regular_file(path, ec))
    fail(label, fs::exists(path, ec) ? "not a regular file" : "no such file");
  Dataset ds(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR,
                        nullptr, nullptr, nullptr));
  if (!ds) fail(label, errors.last("not a raster image GDAL can read"));
  if (GDALGetRasterCount(ds.get()) < 1) fail(label, "has no raster bands");
  return ds;
}

/// The source's coordinate system as WKT: its own, or EPSG:4326 for a bare geotransform whose
/// extent is in degrees. Throws when the raster is not georeferenced.
std::string sourceSrs(GDALDatasetH ds, const std::string& label) {
  std::array<double, 6> gt{};
  const bool hasTransform = GDALGetGeoTransform(ds, gt.data()) == CE_None &&
                            !(gt[0] == 0 && gt[1] == 1 && gt[2] == 0 && gt[3] == 0 && gt[4] == 0 &&
                              gt[5] == 1);
  if (!hasTransform && GDALGetGCPCount(ds) > 0) {
    const char* gcpWkt = GDALGetGCPProjection(ds);
    if (gcpWkt != nullptr && *gcpWkt != '\0') return gcpWkt;
  }
  if (!hasTransform)
    fail(label, "has no georeferencing (no GeoTIFF tags, world file or ground control points); "
                "imagery must be georeferenced, e.g. in EPSG:4326 or EPSG:3857");
  const char* wkt = GDALGetProjectionRef(ds);
  if (wkt != nullptr && *wkt != '\0') return wkt;
  const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
  const double x0 = gt[0], x1 = gt[0] + gt[1] * w + gt[2] * h;
  const double y0 = gt[3], y1 = gt[3] + gt[4] * w + gt[5] * h;
  const auto inside = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  if (!(inside(x0, -180.5, 360.5) && inside(x1, -180.5, 360.5) && inside(y0, -90.5, 90.5) &&
        inside(y1, -90.5, 90.5))) {
    char extent[160];
    std::snprintf(extent, sizeof extent, "%g..%g by %g..%g", std::min(x0, x1), std::max(x0, x1),
                  std::min(y0, y1), std::max(y0, y1));
    fail(label, std::string("has a geotransform but no coordinate system, and its extent (") +
                    extent + ") is not in degrees; add a .prj/.aux.xml or use a GeoTIFF");
  }
  log::info(label + ": no coordinate system given; taking the world file as EPSG:4326 degrees");
  return SRS_WKT_WGS84_LAT_LONG;
}

/// A GDAL utility's argument list.
class Args {
 public:
  Args& add(const std::string& a) {
    list_ = CSLAddString(list_, a.c_str());
    return *this;
  }
  ~Args() { CSLDestroy(list_); }
  Args() = default;
  Args(const Args&) = delete;
  Args& operator=(const Args&) = delete;
  [[nodiscard]] char** get() const { return list_; }

 private:
  char** list_ = nullptr;
};

std::string number(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

/// Paletted or wider-than-8-bit imagery as 8-bit RGB(A)/grey (a virtual dataset over `src`).
Dataset toEightBit(Dataset src, const std::string& label, const GdalErrors& errors) {
  GDALRasterBandH band = GDALGetRasterBand(src.get(), 1);
  const bool paletted = GDALGetRasterColorTable(band) != nullptr;
  const bool wide = GDALGetRasterDataType(band) != GDT_Byte;
  if (!paletted && !wide) return src;
  Args args;
  args.add("-of").add("VRT");
  if (paletted) args.add("-expand").add("rgba");
  if (wide) {
    log::info(label + ": " + GDALGetDataTypeName(GDALGetRasterDataType(band)) +
              " imagery scaled from its range to 8 bits");
    args.add("-ot").add("Byte").add("-scale");
  }
  GDALTranslateOptions* options = GDALTranslateOptionsNew(args.get(), nullptr);
  int usage = 0;
  Dataset out(GDALTranslate("", src.get(), options, &usage));
  GDALTranslateOptionsFree(options);
  if (!out) fail(label, errors.last("cannot convert to 8-bit colour"));
  // The VRT refers to the source: keep it open as long as the VRT (released with the VRT).
  src.release();
  return out;
}

struct Extent {
  double west, south, east, north;
  int width, height;  ///< GDAL's suggested size at the source's resolution
};

/// The source's footprint in EPSG:4326 and the size that keeps its resolution.
Extent geographicExtent(GDALDatasetH ds, const std::string& srcWkt, const std::string& label,
                        const GdalErrors& errors) {
  Args opts;
  opts.add("SRC_SRS=" + srcWkt).add(std::string("DST_SRS=") + SRS_WKT_WGS84_LAT_LONG);
  void* transformer = GDALCreateGenImgProjTransformer2(ds, nullptr, opts.get());
  if (transformer == nullptr)
    fail(label, errors.last("cannot transform its coordinate system to EPSG:4326"));
  std::array<double, 6> gt{};
  int w = 0, h = 0;
  const CPLErr e = GDALSuggestedWarpOutput(ds, GDALGenImgProjTransform, transformer, gt.data(), &w, &h);
  GDALDestroyGenImgProjTransformer(transformer);
  if (e != CE_None || w <= 0 || h <= 0)
    fail(label, errors.last("cannot compute its footprint in EPSG:4326"));
  Extent x{gt[0], gt[3] + gt[5] * h, gt[0] + gt[1] * w, gt[3], w, h};
  // Snap a global raster's edges (rounding in the transform) and keep latitudes on the globe.
  x.south = std::max(x.south, -90.0);
  x.north = std::min(x.north, 90.0);
  if (!(x.east > x.west && x.north > x.south) || !std::isfinite(x.west) || !std::isfinite(x.east))
    fail(label, "its footprint in EPSG:4326 is empty");
  return x;
}

/// Warps `src` onto a latitude/longitude grid in memory.
Dataset warpToGeographic(GDALDatasetH src, const std::string& srcWkt, const Extent& x, int width,
                         int height, bool alpha, const std::string& dataType,
                         const std::string& label, const GdalErrors& errors) {
  const bool downsampling = width < x.width || height < x.height;
  Args args;
  args.add("-of").add("MEM").add("-s_srs").add(srcWkt).add("-t_srs").add("EPSG:4326");
  args.add("-te").add(number(x.west)).add(number(x.south)).add(number(x.east)).add(number(x.north));
  args.add("-ts").add(std::to_string(width)).add(std::to_string(height));
  args.add("-r").add(downsampling ? "average" : "bilinear");
  if (alpha) args.add("-dstalpha");
  if (!dataType.empty()) args.add("-ot").add(dataType).add("-dstnodata").add("nan");
  // Sample the transform on a grid, not only along the edges (sources spanning the globe).
  args.add("-wo").add("SAMPLE_GRID=YES");
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(args.get(), nullptr);
  if (options == nullptr) throw InternalError(label + ": bad GDAL warp options");
  int usage = 0;
  GDALDatasetH source = src;
  Dataset out(GDALWarp("", nullptr, 1, &source, options, &usage));
  GDALWarpAppOptionsFree(options);
  if (!out) fail(label, errors.last("cannot be reprojected to EPSG:4326"));
  return out;
}

/// Reads band `b` (1-based) of `ds` into `out` (pixel stride `stride` bytes), rows flipped so
/// row 0 is the southernmost.
void readByteBand(GDALDatasetH ds, int b, std::uint8_t* out, int stride, const std::string& label,
                  const GdalErrors& errors) {
  const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  if (GDALRasterIO(GDALGetRasterBand(ds, b), GF_Read, 0, 0, w, h, rows.data(), w, h, GDT_Byte, 0, 0) != CE_None)
    fail(label, errors.last("cannot read its pixels (truncated or corrupt?)"));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      out[(static_cast<std::size_t>(h - 1 - r) * static_cast<std::size_t>(w) + static_cast<std::size_t>(c)) *
          static_cast<std::size_t>(stride)] =
          rows[static_cast<std::size_t>(r) * static_cast<std::size_t>(w) + static_cast<std::size_t>(c)];
}

/// The common case with no resampling to do: a north-up EPSG:4326 grey or RGB raster without
/// no-data or alpha, read at its own size (e.g. the embedded Blue Marble), read straight from
/// the source (alpha 255); GDAL's warp of the same grid costs ~0.3 s per 2048 × 1024 image at
/// start-up for the same pixels. False (and `img` untouched) when any of that does not hold.
bool readUnwarped(GDALDatasetH src, const std::string& srcWkt, int width, int height,
                  const std::string& label, const GdalErrors& errors, GeoImage& img) {
  std::array<double, 6> gt{};
  const int w = GDALGetRasterXSize(src), h = GDALGetRasterYSize(src), bands = GDALGetRasterCount(src);
  if (w != width || h != height || (bands != 1 && bands != 3) ||
      GDALGetGeoTransform(src, gt.data()) != CE_None || gt[1] <= 0 || gt[2] != 0 || gt[4] != 0 || gt[5] >= 0)
    return false;
  for (int b = 1; b <= bands; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(src, b);
    int hasNoData = 0;
    (void)GDALGetRasterNoDataValue(band, &hasNoData);
    if (hasNoData != 0 || GDALGetRasterDataType(band) != GDT_Byte ||
        GDALGetRasterColorInterpretation(band) == GCI_AlphaBand || GDALGetMaskFlags(band) != GMF_ALL_VALID)
      return false;
  }
  OGRSpatialReferenceH have = OSRNewSpatialReference(srcWkt.c_str());
  OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(SRS_WKT_WGS84_LAT_LONG);
  const bool same = have != nullptr && wgs84 != nullptr && OSRIsSame(have, wgs84) != 0;
  if (have != nullptr) OSRDestroySpatialReference(have);
  if (wgs84 != nullptr) OSRDestroySpatialReference(wgs84);
  const double west = gt[0], north = gt[3], east = west + gt[1] * w, south = north + gt[5] * h;
  if (!same || west < -180.0 - 1e-9 || east > 180.0 + 1e-9 || south < -90.0 - 1e-9 || north > 90.0 + 1e-9)
    return false;
  img.label = label;
  img.width = w;
  img.height = h;
  img.westDeg = west;
  img.southDeg = south;
  img.eastDeg = east;
  img.northDeg = north;
  img.rgba.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 255);
  for (int c = 0; c < 3; ++c) readByteBand(src, std::min(c + 1, bands), img.rgba.data() + c, 4, label, errors);
  return true;
}

/// An 8-bit GeoImage of the warped dataset `geo` (colour bands + an alpha band last).
GeoImage imageOf(GDALDatasetH geo, const Extent& x, const std::string& label, const GdalErrors& errors) {
  GeoImage img;
  img.label = label;
  img.width = GDALGetRasterXSize(geo);
  img.height = GDALGetRasterYSize(geo);
  img.westDeg = x.west;
  img.southDeg = x.south;
  img.eastDeg = x.east;
  img.northDeg = x.north;
  img.rgba.assign(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 4, 0);
  const int bands = GDALGetRasterCount(geo);  // colour bands + the alpha band
  const int colour = std::min(3, bands - 1);
  for (int c = 0; c < 3; ++c) readByteBand(geo, std::min(c, colour - 1) + 1, img.rgba.data() + c, 4, label, errors);
  readByteBand(geo, bands, img.rgba.data() + 3, 4, label, errors);
  return img;
}

/// An open raster, converted to 8 bits, with its footprint in EPSG:4326.
class GdalImageSource final : public GeoImageSource {
 public:
  GdalImageSource(const std::string& path, const std::string& label) : label_(label) {
    registerGdal();
    GdalErrors errors;
    dataset_ = openRaster(path, label, errors);
    wkt_ = sourceSrs(dataset_.get(), label);
    dataset_ = toEightBit(std::move(dataset_), label, errors);
    extent_ = geographicExtent(dataset_.get(), wkt_, label, errors);
    footprint_ = {extent_.west, extent_.south, extent_.east, extent_.north, extent_.width, extent_.height};
  }

  [[nodiscard]] const GeoFootprint& footprint() const override { return footprint_; }
  [[nodiscard]] const std::string& label() const override { return label_; }

  [[nodiscard]] GeoImage read(double westDeg, double southDeg, double eastDeg, double northDeg, int widthPx,
                              int heightPx) const override {
    GdalErrors errors;
    // The window's size at the source's resolution decides between averaging and bilinear.
    const double cell = footprint_.cellDeg();
    const Extent x{westDeg, southDeg, eastDeg, northDeg,
                   static_cast<int>(std::ceil((eastDeg - westDeg) / cell)),
                   static_cast<int>(std::ceil((northDeg - southDeg) / cell))};
    Dataset geo = warpToGeographic(dataset_.get(), wkt_, x, widthPx, heightPx, true, {}, label_, errors);
    return imageOf(geo.get(), x, label_, errors);
  }

  [[nodiscard]] GeoImage readWhole(const GeoImageRequest& request) const override {
    if (request.maxSizePx < 16 || request.maxSizePx > 16384)
      throw InternalError("imagery size limit out of range: " + std::to_string(request.maxSizePx));
    GdalErrors errors;
    const Extent& x = extent_;
    int width = x.width, height = x.height;
    if (request.square) {
      width = height = request.maxSizePx;
    } else if (std::max(width, height) > request.maxSizePx) {
      const double f = static_cast<double>(request.maxSizePx) / std::max(width, height);
      width = std::max(1, static_cast<int>(std::lround(width * f)));
      height = std::max(1, static_cast<int>(std::lround(height * f)));
    }
    if (GeoImage direct; readUnwarped(dataset_.get(), wkt_, width, height, label_, errors, direct)) return direct;
    Dataset geo = warpToGeographic(dataset_.get(), wkt_, x, width, height, true, {}, label_, errors);
    return imageOf(geo.get(), x, label_, errors);
  }

 private:
  std::string label_;
  Dataset dataset_;
  std::string wkt_;
  Extent extent_{};
  GeoFootprint footprint_;
};

std::atomic<unsigned> gMemoryCounter{0};

/// A file in GDAL's in-memory file system, deleted with this object.
class MemoryFile {
 public:
  MemoryFile(const std::string& path, std::string_view bytes) : path_(path) {
    // GDAL reads the bytes in place; they outlive the file (embedded data or the caller's).
    VSILFILE* f = VSIFileFromMemBuffer(path_.c_str(),
                                       reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                       static_cast<vsi_l_offset>(bytes.size()), FALSE);
    if (f == nullptr) throw InternalError("GDAL: cannot create " + path_);
    VSIFCloseL(f);
  }
  ~MemoryFile() { VSIUnlink(path_.c_str()); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

 private:
  std::string path_;
};

ByteRaster readBytes(const std::string& path, const std::string& label) {
  registerGdal();
  GdalErrors errors;
  Dataset ds = openRaster(path, label, errors);
  const std::string wkt = sourceSrs(ds.get(), label);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(wkt.c_str());
  const bool geographic = srs != nullptr && OSRIsGeographic(srs);
  if (srs != nullptr) OSRDestroySpatialReference(srs);
  std::array<double, 6> gt{};
  if (!geographic || GDALGetGeoTransform(ds.get(), gt.data()) != CE_None || gt[2] != 0 || gt[4] != 0 ||
      gt[1] <= 0 || gt[5] >= 0)
    fail(label, "must be a north-up raster in geographic coordinates (EPSG:4326)");
  ByteRaster r;
  r.width = GDALGetRasterXSize(ds.get());
  r.height = GDALGetRasterYSize(ds.get());
  r.cellLonDeg = gt[1];
  r.cellLatDeg = -gt[5];
  r.westDeg = gt[0];
  r.southDeg = gt[3] + gt[5] * r.height;
  r.values.resize(static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height));
  readByteBand(ds.get(), 1, r.values.data(), 1, label, errors);
  return r;
}


LatLonGrid readGrid(const fs::path& file, int maxSizePx) {
  registerGdal();
  const std::string label = file.string();
  GdalErrors errors;
  Dataset src = openRaster(label, label, errors);
  const std::string srcWkt = sourceSrs(src.get(), label);
  GDALRasterBandH band = GDALGetRasterBand(src.get(), 1);
  int hasNoData = 0;
  const double noData = GDALGetRasterNoDataValue(band, &hasNoData);
  int hasScale = 0, hasOffset = 0;
  const double scale = GDALGetRasterScale(band, &hasScale);
  const double offset = GDALGetRasterOffset(band, &hasOffset);
  const char* unitType = GDALGetRasterUnitType(band);
  const Extent x = geographicExtent(src.get(), srcWkt, label, errors);
  int width = x.width, height = x.height;
  if (std::max(width, height) > maxSizePx) {
    const double s = static_cast<double>(maxSizePx) / std::max(width, height);
    width = std::max(2, static_cast<int>(std::lround(width * s)));
    height = std::max(2, static_cast<int>(std::lround(height * s)));
  }
  // The warp keeps nodata as NaN; scale/offset are applied after it, on the raw values.
  Dataset geo = warpToGeographic(src.get(), srcWkt, x, width, height, false, "Float32", label, errors);
  std::vector<float> rows(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  if (GDALRasterIO(GDALGetRasterBand(geo.get(), 1), GF_Read, 0, 0, width, height, rows.data(), width,
                   height, GDT_Float32, 0, 0) != CE_None)
    fail(label, errors.last("cannot read its values (truncated or corrupt?)"));
  LatLonGrid grid;
  grid.name = "band 1";
  grid.units = unitType != nullptr ? unitType : "";
  grid.width = width;
  grid.height = height;
  grid.dLonDeg = (x.east - x.west) / width;
  grid.dLatDeg = (x.north - x.south) / height;
  grid.lon0Deg = x.west + 0.5 * grid.dLonDeg;
  if (grid.lon0Deg < -180.0) grid.lon0Deg += 360.0;
  grid.lat0Deg = x.south + 0.5 * grid.dLatDeg;
  grid.wrapsLongitude = x.east - x.west >= 359.999;
  grid.values.resize(rows.size());
  std::size_t valid = 0;
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      double v = static_cast<double>(
          rows[static_cast<std::size_t>(height - 1 - r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)]);
      if (hasNoData && v == noData) v = std::nan("");
      if (std::isnan(v)) {
        grid.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] = NAN;
        continue;
      }
      if (!std::isfinite(v)) fail(label, "has a non-finite value");
      v = v * (hasScale ? scale : 1.0) + (hasOffset ? offset : 0.0);
      grid.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] =
          static_cast<float>(v);
      ++valid;
    }
  if (valid == 0) fail(label, "has no valid values (all nodata)");
  return grid;
}

/// In-memory files under /vsimem/ for the image and its world file, removed with this object.
class MemoryImage {
 public:
  MemoryImage(std::string_view bytes, std::string_view worldFile, const std::string& extension)
      : dir_("/vsimem/oceanglobe_" + std::to_string(gMemoryCounter++)), path_(dir_ + "/image." + extension),
        image_(path_, bytes) {
    if (!worldFile.empty()) world_ = std::make_unique<MemoryFile>(dir_ + "/image.wld", worldFile);
  }
  /// The image's path in GDAL's in-memory file system.
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string dir_, path_;
  MemoryFile image_;
  std::unique_ptr<MemoryFile> world_;
};

class GdalRasters final : public GeoRasterBackend {
 public:
  [[nodiscard]] std::unique_ptr<GeoImageSource> open(const std::string& path, const std::string& label) const override {
    return std::make_unique<GdalImageSource>(path, label);
  }
  [[nodiscard]] GeoImage readImageMemory(std::string_view bytes, std::string_view worldFile,
                                         const std::string& extension, const std::string& label,
                                         const GeoImageRequest& request) const override {
    registerGdal();
    const MemoryImage memory(bytes, worldFile, extension);
    return GdalImageSource(memory.path(), label).readWhole(request);
  }
  [[nodiscard]] LatLonGrid readGrid(const fs::path& file, int maxSizePx) const override {
    return data::readGrid(file, maxSizePx);
  }
  [[nodiscard]] ByteRaster readBytes(const fs::path& file) const override {
    return data::readBytes(file.string(), file.string());
  }
  [[nodiscard]] ByteRaster readBytesMemory(std::string_view bytes, std::string_view worldFile,
                                           const std::string& extension, const std::string& label) const override {
    registerGdal();
    const MemoryImage memory(bytes, worldFile, extension);
    return data::readBytes(memory.path(), label);
  }
};

}  // namespace
}  // namespace og::data

extern "C" __attribute__((visibility("default"))) void* oceanglobe_plugin_entry(const og::plugin::Host* host) {
  if (!og::plugin::acceptHost(host)) return nullptr;
  static og::data::GdalRasters rasters;
  return static_cast<og::data::GeoRasterBackend*>(&rasters);
}
