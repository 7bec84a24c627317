#pragma once
// Imagery layers: georeferenced colour rasters draped over the globe and the terrain as their
// albedo. The defaults ship embedded (data/README.md): NASA Visible Earth's "Blue Marble" day
// image and its "Earth at night" city lights, 2048 × 1024 pixels each (about 19.6 km per pixel
// at the equator).
#include <filesystem>
#include <vector>

#include "data/GeoRaster.hpp"

namespace og::data {

/// At most this many `--imagery-layer`s (each one a texture-array layer on the GPU).
inline constexpr int kMaxImageryLayers = 8;
/// Each user imagery layer is resampled to a square of this many pixels on a side over its own
/// latitude/longitude extent (about 21 MiB of GPU memory per layer with its mip-maps): detail
/// finer than extent / 2048 is averaged away (a whole 1° × 1° Sentinel-2 tile keeps ~55 m).
inline constexpr int kImageryLayerSizePx = 2048;

/// Reads one `--imagery-layer FILE` (any georeferenced raster GDAL reads, see readGeoImage),
/// resampled to kImageryLayerSizePx² over its footprint. Throws og::InputError "FILE: problem".
GeoImage loadImageryLayer(const std::filesystem::path& file, int sizePx = kImageryLayerSizePx);

/// Reads the given layers in order (later ones are drawn on top); throws when there are more
/// than kMaxImageryLayers.
std::vector<GeoImage> loadImageryLayers(const std::vector<std::filesystem::path>& files,
                                        int sizePx = kImageryLayerSizePx);

/// The embedded default day colour (Blue Marble), global, sRGB as shipped.
const GeoImage& defaultDayImagery();
/// The embedded default night lights (Earth at night), global, sRGB as shipped.
const GeoImage& defaultNightLights();

}  // namespace og::data
