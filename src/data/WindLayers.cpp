#include "data/WindLayers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <utility>
#include <numbers>

#include "core/Error.hpp"
#include "core/Log.hpp"

namespace og::data {

namespace {

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Distance in cells (8-neighbour chamfer, diagonals √2) from each cell to the nearest cell
/// without data or, where the grid does not continue, to the nearest cell beyond its edge;
/// capped at `cap`. Cells without data get 0, their neighbours and edge cells 1.
std::vector<double> coverageDistance(const std::vector<bool>& valid, int width, int height,
                                     bool wrapColumns, bool openRows, double cap) {
  const auto at = [width](int c, int r) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(c);
  };
  std::vector<double> d(valid.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = valid[i] ? cap : 0.0;
  const double diagonal = std::numbers::sqrt2;
  // Relaxation sweeps, alternating direction; distances are capped, so a few suffice.
  const int sweeps = 2 * (static_cast<int>(std::ceil(cap)) + 1);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const bool forward = sweep % 2 == 0;
    for (int k = 0; k < height; ++k) {
      const int r = forward ? k : height - 1 - k;
      for (int j = 0; j < width; ++j) {
        const int c = forward ? j : width - 1 - j;
        double& here = d[at(c, r)];
        if (here == 0.0) continue;
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            if (dr == 0 && dc == 0) continue;
            const double cost = (dr != 0 && dc != 0) ? diagonal : 1.0;
            int nr = r + dr;
            int nc = c + dc;
            if (nr < 0 || nr >= height) {
              if (openRows) {
                here = std::min(here, cost);
              }
              continue;  // rows reaching the poles: nothing beyond, no edge
            }
            if (nc < 0 || nc >= width) {
              if (!wrapColumns) {
                here = std::min(here, cost);
                continue;
              }
              nc = (nc + width) % width;
            }
            here = std::min(here, d[at(nc, nr)] + cost);
          }
      }
    }
  }
  return d;
}

}  // namespace

/// A timed layer's file, with the steps it read (a few, most recent kept) and the blend weights
/// computed for pairs of steps (the no-data cells of a pair decide them).
class WindLayers::TimedSource {
 public:
  explicit TimedSource(std::shared_ptr<const WindSeries> series) : series_(std::move(series)) {}

  /// The steps around `time`, the weight rounded to a multiple of 1/kWeightSteps (0 or 1
  /// collapse to one step), so that equal choices give identical winds.
  [[nodiscard]] StepChoice choose(std::optional<UtcTime> time) const {
    StepChoice c = series_->choose(time);
    const long q = std::lround(c.weight * kWeightSteps);
    if (q <= 0) {
      c.second = c.first;
      c.weight = 0.0;
    } else if (q >= kWeightSteps) {
      c.first = c.second;
      c.weight = 0.0;
    } else {
      c.weight = static_cast<double>(q) / kWeightSteps;
    }
    return c;
  }

  /// The layer for a choice made by choose().
  std::shared_ptr<const Layer> layerAt(const StepChoice& c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (last_ && c.first == last_choice_.first && c.second == last_choice_.second &&
        c.weight == last_choice_.weight)
      return last_;
    WindGrid grid = c.first == c.second ? step(c.first) : blendWind(step(c.first), step(c.second), c.weight);
    const auto pair = std::make_pair(c.first, c.second);
    const auto cached = weights_.find(pair);
    std::shared_ptr<const Layer> layer =
        makeLayer(std::move(grid), cached == weights_.end() ? nullptr : &cached->second);
    if (cached == weights_.end()) {
      if (weights_.size() >= kCachedPairs) weights_.clear();
      weights_.emplace(pair, layer->weight);
    }
    last_choice_ = c;
    last_ = layer;
    return layer;
  }

  /// The strongest wind of any step, m/s (every step read once, then remembered).
  double maxSpeedMs() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (maxSpeedMs_ < 0.0) maxSpeedMs_ = series_->maxSpeedMs();
    return maxSpeedMs_;
  }

 private:
  static constexpr std::size_t kCachedSteps = 4;
  static constexpr std::size_t kCachedPairs = 4;

  const WindGrid& step(std::size_t i) {
    const auto found = steps_.find(i);
    if (found != steps_.end()) return found->second;
    if (steps_.size() >= kCachedSteps) {  // drop the step read longest ago
      steps_.erase(order_.front());
      order_.erase(order_.begin());
    }
    order_.push_back(i);
    return steps_.emplace(i, series_->readStep(i)).first->second;
  }

  std::shared_ptr<const WindSeries> series_;
  std::mutex mutex_;
  std::map<std::size_t, WindGrid> steps_;
  std::vector<std::size_t> order_;  // steps_ keys, oldest first
  std::map<std::pair<std::size_t, std::size_t>, LatLonGrid> weights_;
  StepChoice last_choice_;
  std::shared_ptr<const Layer> last_;
  double maxSpeedMs_ = -1.0;
};

WindLayers::WindLayers(WindVector fallback) : fallback_(fallback) {}

WindLayers WindLayers::load(const std::vector<std::string>& specs, WindVector fallback,
                            std::optional<UtcTime> time) {
  WindLayers layers(fallback);
  // "default" names the embedded month of global winds (data/README.md).
  for (const std::string& spec : specs) {
    if (spec == "default") {
      layers.push(defaultWind());
      continue;
    }
    std::shared_ptr<const WindSeries> series = WindSeries::open(spec);
    const FieldDescription& axis = series->axis();
    if (time && !axis.climatology && axis.times.size() > 1 &&
        (time->unixSeconds < axis.times.front().unixSeconds || time->unixSeconds > axis.times.back().unixSeconds))
      log::warn(series->label() + ": " + time->toIso8601() + " is outside the file's time steps (" +
                axis.times.front().toIso8601() + " to " + axis.times.back().toIso8601() +
                "); the wind holds the nearest step until the clock reaches the file");
    if (axis.steps() > 1)
      layers.push(std::move(series), time);
    else
      layers.push(series->readStep(0));
  }
  return layers;
}

void WindLayers::push(WindGrid layer) {
  layers_.push_back(makeLayer(std::move(layer)));
  sources_.push_back(nullptr);
}

void WindLayers::push(std::shared_ptr<const WindSeries> series, std::optional<UtcTime> time) {
  auto source = std::make_shared<TimedSource>(std::move(series));
  const StepChoice c = source->choose(time);
  layers_.push_back(source->layerAt(c));
  sources_.push_back(std::move(source));
  key_.steps.push_back(c.first);
  key_.steps.push_back(c.second);
  key_.weights.push_back(static_cast<int>(std::lround(c.weight * kWeightSteps)));
}

bool WindLayers::timeVarying() const {
  return std::any_of(sources_.begin(), sources_.end(), [](const auto& s) { return s != nullptr; });
}

WindTimeKey WindLayers::timeKey(std::optional<UtcTime> time) const {
  WindTimeKey key;
  for (const auto& source : sources_) {
    if (!source) continue;
    const StepChoice c = source->choose(time);
    key.steps.push_back(c.first);
    key.steps.push_back(c.second);
    key.weights.push_back(static_cast<int>(std::lround(c.weight * kWeightSteps)));
  }
  return key;
}

WindLayers WindLayers::at(std::optional<UtcTime> time) const {
  WindLayers out = *this;
  for (std::size_t i = 0; i < sources_.size(); ++i)
    if (sources_[i]) out.layers_[i] = sources_[i]->layerAt(sources_[i]->choose(time));
  out.key_ = timeKey(time);
  return out;
}

double WindLayers::maxSpeedMs() const {
  double strongest = std::hypot(fallback_.uMs, fallback_.vMs);
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    if (sources_[i]) {
      strongest = std::max(strongest, sources_[i]->maxSpeedMs());
      continue;
    }
    const Layer& l = *layers_[i];
    for (std::size_t k = 0; k < l.grid.u.values.size(); ++k)
      if (l.weight.values[k] > 0.0f)
        strongest = std::max(strongest, std::hypot(static_cast<double>(l.grid.u.values[k]),
                                                   static_cast<double>(l.grid.v.values[k])));
  }
  return strongest;
}

std::shared_ptr<const WindLayers::Layer> WindLayers::makeLayer(WindGrid layer, const LatLonGrid* weight) {
  LatLonGrid& u = layer.u;
  LatLonGrid& v = layer.v;
  const std::size_t cells = static_cast<std::size_t>(std::max(u.width, 0)) *
                            static_cast<std::size_t>(std::max(u.height, 0));
  if (u.width < 2 || u.height < 2 || u.values.size() != cells || v.width != u.width ||
      v.height != u.height || v.values.size() != cells || v.lon0Deg != u.lon0Deg ||
      v.lat0Deg != u.lat0Deg || v.dLonDeg != u.dLonDeg || v.dLatDeg != u.dLatDeg ||
      v.wrapsLongitude != u.wrapsLongitude)
    throw InputError(layer.label + ": wind components must share one grid of at least 2 x 2");

  std::vector<bool> valid(cells);
  for (std::size_t i = 0; i < cells; ++i)
    valid[i] = std::isfinite(u.values[i]) && std::isfinite(v.values[i]);
  auto out = std::make_shared<Layer>();
  if (weight != nullptr) {
    out->weight = *weight;
  } else {
    const std::vector<double> distance = coverageDistance(
        valid, u.width, u.height, u.wrapsLongitude, !u.coversPoles(), kBlendCells + 1.0);
    // Blend over at most kBlendCells, less when the coverage is narrower, so every layer reaches
    // full weight somewhere. Edge cells (distance 1) get weight 0.
    double deepest = 0.0;
    for (double d : distance) deepest = std::max(deepest, d - 1.0);
    if (deepest <= 0.0)
      throw InputError(layer.label +
                       ": the wind field has no cell with data at least one cell inside the edge "
                       "of its coverage (too small or too sparse to use)");
    const double blend = std::min(kBlendCells, deepest);
    out->weight = u;
    out->weight.name = std::string("weight");  // (a literal trips GCC 12's false -Wrestrict)
    out->weight.units = std::string("1");
    for (std::size_t i = 0; i < cells; ++i)
      out->weight.values[i] = static_cast<float>(smoothstep(0.0, blend, distance[i] - 1.0));
  }
  for (std::size_t i = 0; i < cells; ++i) {
    if (!valid[i]) {
      u.values[i] = 0.0f;  // weight 0 here: the value only keeps bilinear sums finite
      v.values[i] = 0.0f;
    }
  }
  out->grid = std::move(layer);
  return out;
}

WindVector WindLayers::sample(double latDeg, double lonDeg) const {
  WindVector w = fallback_;
  for (const auto& held : layers_) {
    const Layer& layer = *held;
    const float weight = layer.weight.sample(latDeg, lonDeg);
    if (!(weight > 0.0f)) continue;  // outside the grid (NaN) or at/after its edge
    const float u = layer.grid.u.sample(latDeg, lonDeg);
    const float v = layer.grid.v.sample(latDeg, lonDeg);
    if (!std::isfinite(u) || !std::isfinite(v)) continue;
    const double a = std::min(static_cast<double>(weight), 1.0);
    w.uMs += a * (static_cast<double>(u) - w.uMs);
    w.vMs += a * (static_cast<double>(v) - w.vMs);
  }
  return w;
}

WindRaster WindLayers::rasterize(int width, int height) const {
  constexpr int kMaxSize = 16384;
  if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize)
    throw InputError("wind raster size " + std::to_string(width) + " x " +
                     std::to_string(height) + " is outside 1..16384");
  WindRaster raster;
  raster.width = width;
  raster.height = height;
  raster.uv.resize(2 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  // Rows in parallel (sample() only reads): a timed layer re-rasterises while a recording runs.
  const auto rows = [&](int first, int last) {
    for (int r = first; r < last; ++r) {
      const double lat = -90.0 + (r + 0.5) * 180.0 / height;
      for (int c = 0; c < width; ++c) {
        const double lon = -180.0 + (c + 0.5) * 360.0 / width;
        const WindVector w = sample(lat, lon);
        const std::size_t i =
            2 * (static_cast<std::size_t>(r) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(c));
        raster.uv[i] = static_cast<float>(w.uMs);
        raster.uv[i + 1] = static_cast<float>(w.vMs);
      }
    }
  };
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::min(8, height));
  {
    std::vector<std::jthread> pool;  // joined at the end of the scope, also on an exception
    for (int t = 1; t < threads; ++t) pool.emplace_back(rows, height * t / threads, height * (t + 1) / threads);
    rows(0, height / threads);
  }
  return raster;
}

}  // namespace og::data
