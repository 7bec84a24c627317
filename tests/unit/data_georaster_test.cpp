// GDAL raster reader: synthetic GeoTIFFs written here with GDAL (geographic and Web Mercator)
// land where they belong; a PNG with a world file is taken as degrees; unreadable, truncated and
// non-georeferenced files are refused with the file's name; GeoTIFF DEMs are validated like
// NetCDF ones; the embedded default imagery is where the continents are.
#include <gtest/gtest.h>
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "data/GeoRaster.hpp"
#include "data/Imagery.hpp"
#include "support/DataFixtures.hpp"
#include "support/ExpectError.hpp"
#include "support/GeoTiffWriter.hpp"

namespace fs = std::filesystem;
using og::data::GeoImage;
using og::test::expectInputError;

namespace {

fs::path outDir() { return og::test::fixtureDir("data_georaster"); }

/// The quadrant colours of the fixtures, split at (45°N, 15°E): NW red, NE green, SW blue,
/// SE white.
std::array<std::uint8_t, 3> quadrant(double latDeg, double lonDeg) {
  if (latDeg >= 45.0) return lonDeg < 15.0 ? std::array<std::uint8_t, 3>{255, 0, 0} : std::array<std::uint8_t, 3>{0, 255, 0};
  return lonDeg < 15.0 ? std::array<std::uint8_t, 3>{0, 0, 255} : std::array<std::uint8_t, 3>{255, 255, 255};
}

/// A 3-band GeoTIFF over 10..20°E, 40..50°N with the quadrant colours, in EPSG:4326 or 3857.
fs::path writeQuadrants(const std::string& name, int epsg, const std::string& driver = "GTiff") {
  return og::test::writeGeoRaster(outDir() / name, epsg, 200, 200, {10.0, 20.0, 40.0, 50.0}, quadrant, driver);
}

/// The colour of `img` at a latitude/longitude (nearest pixel).
std::array<int, 4> colourAt(const GeoImage& img, double latDeg, double lonDeg) {
  const int c = static_cast<int>((lonDeg - img.westDeg) / (img.eastDeg - img.westDeg) * img.width);
  const int r = static_cast<int>((latDeg - img.southDeg) / (img.northDeg - img.southDeg) * img.height);
  return {img.at(c, r, 0), img.at(c, r, 1), img.at(c, r, 2), img.at(c, r, 3)};
}

void expectQuadrants(const GeoImage& img) {
  EXPECT_NEAR(img.westDeg, 10.0, 0.05);
  EXPECT_NEAR(img.eastDeg, 20.0, 0.05);
  EXPECT_NEAR(img.southDeg, 40.0, 0.05);
  EXPECT_NEAR(img.northDeg, 50.0, 0.05);
  for (double lat : {41.0, 44.0, 46.0, 49.0})
    for (double lon : {11.0, 14.0, 16.0, 19.0}) {
      const auto want = quadrant(lat, lon);
      const auto got = colourAt(img, lat, lon);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(got[static_cast<std::size_t>(k)], want[static_cast<std::size_t>(k)], 8)
            << "channel " << k << " at " << lat << "N " << lon << "E";
      EXPECT_EQ(got[3], 255);
    }
}

}  // namespace

TEST(GeoRaster, GeographicGeoTiffLandsWhereItBelongs) {
  const GeoImage img = og::data::readGeoImage(writeQuadrants("geo4326.tif", 4326));
  expectQuadrants(img);
}

TEST(GeoRaster, WebMercatorGeoTiffIsReprojected) {
  const GeoImage img = og::data::readGeoImage(writeQuadrants("merc3857.tif", 3857));
  expectQuadrants(img);
  // Mercator stretches the north: the 45° split lies north of the raster's middle row there,
  // but after reprojection it sits at the middle of the latitude range.
  EXPECT_EQ(colourAt(img, 45.3, 11.0)[0], 255);
  EXPECT_EQ(colourAt(img, 44.7, 11.0)[2], 255);
}

TEST(GeoRaster, SquareRequestResamplesToTheLayerSize) {
  const GeoImage img = og::data::readGeoImage(writeQuadrants("square.tif", 4326), {.maxSizePx = 64, .square = true});
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 64);
  expectQuadrants(img);
}

TEST(GeoRaster, PngWithWorldFileIsTakenAsDegrees) {
  const fs::path png = outDir() / "world.png";
  {
    const fs::path tif = writeQuadrants("world_src.tif", 4326);
    GDALDatasetH src = GDALOpen(tif.c_str(), GA_ReadOnly);
    GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName("PNG"), png.c_str(), src, FALSE, nullptr, nullptr, nullptr);
    GDALClose(out);
    GDALClose(src);
    fs::remove(fs::path(png.string() + ".aux.xml"));
    std::ofstream(outDir() / "world.pgw") << "0.05\n0\n0\n-0.05\n10.025\n49.975\n";
  }
  expectQuadrants(og::data::readGeoImage(png));
}

TEST(GeoRaster, BadFilesAreRefusedWithTheirName) {
  const fs::path missing = outDir() / "missing.tif";
  expectInputError(missing.string(), "no such file", [&] { (void)og::data::readGeoImage(missing); });
  const fs::path garbage = outDir() / "garbage.tif";
  std::ofstream(garbage) << "this is not an image at all";
  expectInputError(garbage.string(), "", [&] { (void)og::data::readGeoImage(garbage); });
  // A GeoTIFF cut in half: the header and georeferencing survive, the pixels do not.
  const fs::path whole = writeQuadrants("whole.tif", 4326);
  const fs::path truncated = outDir() / "truncated.tif";
  fs::copy_file(whole, truncated, fs::copy_options::overwrite_existing);
  fs::resize_file(truncated, fs::file_size(whole) / 2);
  expectInputError(truncated.string(), "", [&] { (void)og::data::readGeoImage(truncated); });
  // A plain PNG: readable, but nowhere on Earth.
  const fs::path plain = outDir() / "plain.png";
  {
    GDALDatasetH src = GDALOpen(whole.c_str(), GA_ReadOnly);
    GDALDatasetH mem = GDALCreateCopy(GDALGetDriverByName("MEM"), "", src, FALSE, nullptr, nullptr, nullptr);
    const double identity[6] = {0, 1, 0, 0, 0, 1};
    GDALSetGeoTransform(mem, const_cast<double*>(identity));
    GDALSetProjection(mem, "");
    char* noWorld[] = {const_cast<char*>("WORLDFILE=NO"), nullptr};
    GDALClose(GDALCreateCopy(GDALGetDriverByName("PNG"), plain.c_str(), mem, FALSE, noWorld, nullptr, nullptr));
    GDALClose(mem);
    GDALClose(src);
    fs::remove(fs::path(plain.string() + ".aux.xml"));
  }
  expectInputError(plain.string(), "no georeferencing", [&] { (void)og::data::readGeoImage(plain); });
}

namespace {
/// A Float32 GeoTIFF DEM over 10..11°E, 45..46°N: h = 1000 + 100 * column / (w - 1); one
/// cell set to `spike`.
fs::path writeDem(const std::string& name, float spike) {
  GDALAllRegister();
  const fs::path file = outDir() / name;
  const int w = 11, h = 11;
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), file.c_str(), w, h, 1, GDT_Float32, nullptr);
  GDALSetProjection(ds, SRS_WKT_WGS84_LAT_LONG);
  std::array<double, 6> gt{10.0, 1.0 / w, 0, 46.0, 0, -1.0 / h};
  GDALSetGeoTransform(ds, gt.data());
  std::vector<float> v(static_cast<std::size_t>(w * h));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) v[static_cast<std::size_t>(r * w + c)] = 1000.0f + 10.0f * static_cast<float>(c);
  v[static_cast<std::size_t>(2 * w + 3)] = spike;  // row 2 from the north, column 3
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0), CE_None);
  GDALSetRasterNoDataValue(GDALGetRasterBand(ds, 1), -9999.0);
  GDALClose(ds);
  return file;
}
}  // namespace

TEST(GeoRaster, GeoTiffDemIsAnElevationLayer) {
  const og::data::LatLonGrid g = og::data::readElevationFile(writeDem("dem.tif", -9999.0f));
  EXPECT_EQ(g.width, 11);
  EXPECT_EQ(g.height, 11);
  EXPECT_NEAR(g.lon0Deg, 10.0 + 0.5 / 11, 1e-9);
  EXPECT_NEAR(g.lat0Deg, 45.0 + 0.5 / 11, 1e-9);
  EXPECT_NEAR(g.at(4, 0), 1040.0f, 1e-3);        // row 0 is the south
  EXPECT_TRUE(std::isnan(g.at(3, 11 - 1 - 2)));  // the nodata cell
  EXPECT_NEAR(g.sample(45.5, 10.5), 1050.0f, 1.0f);
}

TEST(GeoRaster, GeoTiffDemOutOfRangeIsRefusedWithValueAndPlace) {
  const fs::path dem = writeDem("dem_spike.tif", 20000.0f);
  expectInputError(dem.string(), "20000 m at latitude 45.77, longitude 10.32", [&] { (void)og::data::readElevationFile(dem); });
}

TEST(Imagery, DefaultDayImageryHasTheContinents) {
  const GeoImage& day = og::data::defaultDayImagery();
  ASSERT_EQ(day.width, 2048);
  ASSERT_EQ(day.height, 1024);
  EXPECT_TRUE(day.coversGlobe());
  const auto sahara = colourAt(day, 23.0, 12.0);  // Libyan/Algerian erg: tan, red > green > blue
  EXPECT_GT(sahara[0], sahara[1]);
  EXPECT_GT(sahara[1], sahara[2] + 20);
  EXPECT_GT(sahara[0], 150);
  const auto congo = colourAt(day, -1.0, 22.0);  // Congo basin rain forest: green
  EXPECT_GT(congo[1], congo[0]);
  EXPECT_GT(congo[1], congo[2]);
  const auto pacific = colourAt(day, 0.0, -150.0);  // open ocean: blue
  EXPECT_GT(pacific[2], pacific[0] + 20);
}

TEST(Imagery, DefaultNightLightsAreOnTheCities) {
  const GeoImage& night = og::data::defaultNightLights();
  ASSERT_EQ(night.width, 2048);
  const auto lum = [&](double lat, double lon) {
    const auto c = colourAt(night, lat, lon);
    return c[0] + c[1] + c[2];
  };
  // The Netherlands/Ruhr and the US north-east against the central Sahara and the Pacific.
  EXPECT_GT(lum(51.5, 6.5) + lum(40.7, -74.0), 100);
  EXPECT_LT(lum(23.0, 12.0) + lum(0.0, -150.0), 30);
}
