#pragma once
// A stack of wind layers over a constant wind: the wind the ocean sees at any point.
//
// Layers are ordered bottom first. Each covers the cells of its grid that hold data; towards
// the edge of that coverage (a regional grid's border, or cells without data) its weight falls
// smoothly to zero over a few grid cells, so the wind blends into the layer beneath (or the
// constant wind) with no seam: sample() is continuous everywhere.
//
// Layers read from files with several time steps follow the clock: at(time) gives the stack at
// any instant, each such layer blended linearly between the two steps around it (clamped to the
// file's first/last step; cyclic through the year end for a climatology). The blend weight is
// quantised to 1/kWeightSteps, so a stack at two nearby times is the same stack (timeKey tells
// a renderer when its wind texture must change) and a frame's wind never depends on the frames
// rendered before it. Steps read are cached, so a recording reads each step once.
//
// Units: m/s for wind components, degrees for positions. u is the eastward component, v the
// northward one (the direction the air moves towards, like the files' u/v).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Time.hpp"
#include "data/LatLonGrid.hpp"
#include "data/WindField.hpp"
#include "geo/Wind.hpp"

namespace og::data {

/// A horizontal wind vector, m/s: eastward and northward components (geo/Wind.hpp; a speed and
/// direction become one with geo::Wind::vector()).
using WindVector = geo::WindVector;

/// A global equirectangular u/v grid for a GPU texture. Cell (column c, row r) has its centre at
/// longitude −180 + (c + ½)·360/width and latitude −90 + (r + ½)·180/height; rows run south to
/// north. `uv` is row-major with two floats per cell: u then v, m/s (an RG32F texture; texture
/// coordinate s = (lon + 180)/360 with wrapping, t = (lat + 90)/180 clamped).
struct WindRaster {
  int width = 0;
  int height = 0;
  std::vector<float> uv;  ///< 2 · width · height floats
};

/// Where the timed layers of a stack stand at an instant: per layer the two steps and the
/// quantised blend weight (0..kWeightSteps). Equal keys give identical winds.
struct WindTimeKey {
  std::vector<std::size_t> steps;  ///< first, second per timed layer
  std::vector<int> weights;        ///< per timed layer
  bool operator==(const WindTimeKey&) const = default;
};

class WindLayers {
 public:
  /// Width of the blend at a layer's edge, in the layer's grid cells (less for small grids).
  static constexpr double kBlendCells = 3.0;
  /// Blend weights between two time steps are multiples of 1/kWeightSteps: with hourly steps
  /// the wind changes in 36 s increments of 1 % of the hourly change (invisible), and a wind
  /// texture is rebuilt at most kWeightSteps times per pair of steps.
  static constexpr int kWeightSteps = 100;

  /// A stack with no layers: the wind is `fallback` everywhere.
  explicit WindLayers(WindVector fallback = {});

  /// Reads `--wind-layer` specs "FILE[:U,V]" (bottom first) at `time` (see readWind) over the
  /// constant `fallback`; the spec "default" is the embedded month of global winds. Files with
  /// several time steps stay open so that at() can move them to other times. Throws
  /// og::InputError "FILE: problem" for any bad file.
  static WindLayers load(const std::vector<std::string>& specs, WindVector fallback,
                         std::optional<UtcTime> time);

  /// Puts a layer that follows the clock on top of the stack, at `time`.
  void push(std::shared_ptr<const WindSeries> series, std::optional<UtcTime> time);

  /// True when some layer has several time steps (at() then changes the winds).
  [[nodiscard]] bool timeVarying() const;
  /// The steps and quantised weights of the timed layers at `time` (empty without any).
  [[nodiscard]] WindTimeKey timeKey(std::optional<UtcTime> time) const;
  /// The key of the winds this stack holds now (load time, or the time given to at()).
  [[nodiscard]] const WindTimeKey& timeKey() const { return key_; }
  /// The stack at `time`: timed layers re-blended (from cached steps), the others shared.
  [[nodiscard]] WindLayers at(std::optional<UtcTime> time) const;
  /// The strongest wind any layer holds at any of its time steps, m/s (reads every step of
  /// the timed layers once): wave patterns made for it hold the stack at every time.
  [[nodiscard]] double maxSpeedMs() const;

  /// Puts a layer on top of the stack. u and v must share one geometry, and some cell with data
  /// (NaN = none) must lie at least one cell inside the edge of the coverage, or the layer
  /// would contribute nothing: throws og::InputError "LABEL: problem" otherwise.
  void push(WindGrid layer);

  /// The wind at a point (degrees north, degrees east, any longitude), m/s.
  [[nodiscard]] WindVector sample(double latDeg, double lonDeg) const;

  /// The wind on a global width × height grid of cell centres (see WindRaster).
  /// Throws og::InputError for sizes outside 1..16384.
  [[nodiscard]] WindRaster rasterize(int width, int height) const;

  [[nodiscard]] WindVector fallback() const { return fallback_; }
  [[nodiscard]] std::size_t size() const { return layers_.size(); }
  /// Layer `i` (0 = bottom): label, time, geometry. Its u/v hold 0 where the file had no data.
  [[nodiscard]] const WindGrid& layer(std::size_t i) const { return layers_.at(i)->grid; }
  /// Layer `i`'s blend weight grid (same geometry, 0..1): 0 at the edge of its coverage.
  [[nodiscard]] const LatLonGrid& weight(std::size_t i) const { return layers_.at(i)->weight; }

 private:
  struct Layer {
    WindGrid grid;      // u, v with no-data cells set to 0 (their weight is 0)
    LatLonGrid weight;  // blend weight per cell, 0..1
  };
  class TimedSource;  // a WindSeries with its cache of steps and weights
  /// The layer for `grid` (NaN = no data); `weight` reuses a blend weight computed for the
  /// same no-data cells. Throws as push does.
  static std::shared_ptr<const Layer> makeLayer(WindGrid grid, const LatLonGrid* weight = nullptr);

  WindVector fallback_;
  std::vector<std::shared_ptr<const Layer>> layers_;        // shared between stacks at()
  std::vector<std::shared_ptr<TimedSource>> sources_;       // per layer; nullptr = fixed
  WindTimeKey key_;
};

}  // namespace og::data
