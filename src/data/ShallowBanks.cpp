#include "data/ShallowBanks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"
#include "data/LandMask.hpp"

namespace og::data {

namespace {
constexpr double kKmPerDeg = 111.32;  // along a meridian (mean), km per degree
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

/// Cell geometry and 8-neighbourhood of a LatLonGrid (across the seam when it wraps).
struct Cells {
  const LatLonGrid& g;
  [[nodiscard]] std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(g.width) + static_cast<std::size_t>(column);
  }
  [[nodiscard]] int column(std::size_t i) const { return static_cast<int>(i % static_cast<std::size_t>(g.width)); }
  [[nodiscard]] int row(std::size_t i) const { return static_cast<int>(i / static_cast<std::size_t>(g.width)); }
  [[nodiscard]] double latDeg(std::size_t i) const { return g.lat0Deg + row(i) * g.dLatDeg; }
  [[nodiscard]] double lonDeg(std::size_t i) const { return g.lon0Deg + column(i) * g.dLonDeg; }
  [[nodiscard]] double areaKm2(std::size_t i) const {
    return g.dLatDeg * kKmPerDeg * g.dLonDeg * kKmPerDeg * std::max(std::cos(latDeg(i) * kDegToRad), 0.0);
  }
  /// Calls f(neighbour, distance between the centres in km) for each of the 8 neighbours.
  void forNeighbours(std::size_t i, const std::function<void(std::size_t, double)>& f) const {
    const int c = column(i), r = row(i);
    const double dx = g.dLonDeg * kKmPerDeg * std::max(std::cos(latDeg(i) * kDegToRad), 0.01);
    const double dy = g.dLatDeg * kKmPerDeg;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if (dr == 0 && dc == 0) continue;
        const int rr = r + dr;
        int cc = c + dc;
        if (rr < 0 || rr >= g.height) continue;
        if (g.wrapsLongitude)
          cc = (cc + g.width) % g.width;
        else if (cc < 0 || cc >= g.width)
          continue;
        f(index(cc, rr), std::hypot(dc * dx, dr * dy));
      }
  }
};

bool isPlaceholder(float v) { return v == kEtopoPlaceholderM; }

/// The 8-connected patch of placeholder cells holding `seed`, marking them in `seen`.
std::vector<std::size_t> patchFrom(const Cells& cells, std::size_t seed, std::vector<std::uint8_t>& seen) {
  std::vector<std::size_t> patch{seed}, stack{seed};
  seen[seed] = 1;
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    cells.forNeighbours(i, [&](std::size_t n, double) {
      if (seen[n] != 0 || !isPlaceholder(cells.g.values[n])) return;
      seen[n] = 1;
      patch.push_back(n);
      stack.push_back(n);
    });
  }
  return patch;
}

/// Whether a patch is a placeholder plateau (ShallowBanks.hpp's rules), filling `p`.
bool isPlateau(const Cells& cells, const std::vector<std::size_t>& patch, const std::vector<std::uint8_t>& inPatch,
               Plateau& p) {
  bool block = false;
  for (std::size_t i : patch) {
    p.areaKm2 += cells.areaKm2(i);
    p.centreLatDeg += cells.latDeg(i) / static_cast<double>(patch.size());
    p.centreLonDeg += cells.lonDeg(i) / static_cast<double>(patch.size());
    const int c = cells.column(i), r = cells.row(i);
    if (r + 1 < cells.g.height && (c + 1 < cells.g.width || cells.g.wrapsLongitude)) {
      const int c1 = (c + 1) % cells.g.width;
      block = block || (inPatch[cells.index(c1, r)] != 0 && inPatch[cells.index(c, r + 1)] != 0 &&
                        inPatch[cells.index(c1, r + 1)] != 0);
    }
  }
  if (p.areaKm2 < kPlateauMinAreaKm2 || !block) return false;
  int rim = 0, terrace = 0;
  for (std::size_t i : patch)
    cells.forNeighbours(i, [&](std::size_t n, double) {
      if (inPatch[n] != 0) return;
      ++rim;
      const float v = cells.g.values[n];
      if (v == kEtopoPlaceholderM + 1.0f || v == kEtopoPlaceholderM - 1.0f) ++terrace;
    });
  return 2 * terrace < rim;
}

/// Whether the grid cell `i` holds land: the layer's own (at or above 0 m) or, with a mask,
/// any GSHHG land cell inside it.
bool holdsLand(const Cells& cells, std::size_t i, const LandMask* mask) {
  const float v = cells.g.values[i];
  if (std::isfinite(v) && v >= 0.0f) return true;
  if (mask == nullptr) return false;
  const double d = mask->cellDeg();
  const int c0 = static_cast<int>(std::floor((cells.lonDeg(i) - 0.5 * cells.g.dLonDeg - mask->westDeg()) / d));
  const int c1 = static_cast<int>(std::floor((cells.lonDeg(i) + 0.5 * cells.g.dLonDeg - mask->westDeg()) / d));
  const int r0 = std::max(static_cast<int>(std::floor((cells.latDeg(i) - 0.5 * cells.g.dLatDeg - mask->southDeg()) / d)), 0);
  const int r1 = std::min(static_cast<int>(std::floor((cells.latDeg(i) + 0.5 * cells.g.dLatDeg - mask->southDeg()) / d)),
                          mask->height() - 1);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      if (mask->cell(((c % mask->width()) + mask->width()) % mask->width(), r)) return true;
  return false;
}
}  // namespace

std::vector<Plateau> findPlaceholderPlateaus(const LatLonGrid& grid) {
  std::vector<Plateau> plateaus;
  if (grid.width <= 0 || grid.height <= 0 ||
      grid.values.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height))
    return plateaus;
  const Cells cells{grid};
  std::vector<std::uint8_t> seen(grid.values.size(), 0), inPatch(grid.values.size(), 0);
  for (std::size_t i = 0; i < grid.values.size(); ++i) {
    if (seen[i] != 0 || !isPlaceholder(grid.values[i])) continue;
    std::vector<std::size_t> patch = patchFrom(cells, i, seen);
    for (std::size_t j : patch) inPatch[j] = 1;
    Plateau p;
    if (isPlateau(cells, patch, inPatch, p)) {
      p.cells = std::move(patch);
      plateaus.push_back(std::move(p));
    } else {
      for (std::size_t j : patch) inPatch[j] = 0;
    }
  }
  return plateaus;
}

BankCorrection correctShallowBanks(LatLonGrid& grid, const LandMask* mask) {
  BankCorrection result;
  const std::vector<Plateau> plateaus = findPlaceholderPlateaus(grid);
  result.plateaus = static_cast<int>(plateaus.size());
  if (plateaus.empty()) return result;
  const Cells cells{grid};
  // The domain: the plateaus and their shallower rim cells (the placeholder mixed with land by
  // an average, as in ETOPO20), 1 = plateau, 2 = rim.
  std::vector<std::uint8_t> domain(grid.values.size(), 0);
  for (const Plateau& p : plateaus)
    for (std::size_t i : p.cells) domain[i] = 1;
  for (const Plateau& p : plateaus)
    for (std::size_t i : p.cells)
      cells.forNeighbours(i, [&](std::size_t n, double) {
        const float v = grid.values[n];
        if (domain[n] == 0 && v > kEtopoPlaceholderM && v < 0.0f) domain[n] = 2;
      });
  // Distance to land through the domain (Dijkstra from every land cell in or next to it), km.
  std::unordered_map<std::size_t, double> distKm;
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (std::size_t i = 0; i < grid.values.size(); ++i) {
    if (domain[i] == 0) continue;
    if (holdsLand(cells, i, mask)) {
      distKm[i] = 0.0;
      queue.emplace(0.0, i);
    }
    cells.forNeighbours(i, [&](std::size_t n, double) {
      if (domain[n] == 0 && !distKm.contains(n) && holdsLand(cells, n, mask)) {
        distKm[n] = 0.0;
        queue.emplace(0.0, n);
      }
    });
  }
  const double reachKm = (-static_cast<double>(kEtopoPlaceholderM) - kBankShoreDepthM) / kBankDepthPerKm;
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > distKm[i] || d > reachKm) continue;
    cells.forNeighbours(i, [&](std::size_t n, double stepKm) {
      if (domain[n] == 0) return;
      const auto it = distKm.find(n);
      if (it != distKm.end() && it->second <= d + stepKm) return;
      distKm[n] = d + stepKm;
      queue.emplace(d + stepKm, n);
    });
  }
  grid.keepDepth.assign(grid.values.size(), 0.0f);
  result.minDepthM = std::numeric_limits<float>::max();
  for (const auto& [i, d] : distKm) {
    if (domain[i] == 0) continue;
    const auto depth = static_cast<float>(kBankShoreDepthM + kBankDepthPerKm * d);
    if (depth >= -kEtopoPlaceholderM) continue;  // as deep as the placeholder: left alone
    grid.values[i] = -depth;
    grid.keepDepth[i] = 1.0f;
    ++result.cells;
    result.minDepthM = std::min(result.minDepthM, depth);
    result.maxDepthM = std::max(result.maxDepthM, depth);
  }
  if (result.cells == 0) {
    grid.keepDepth.clear();
    result.minDepthM = 0.0f;
  }
  return result;
}

ElevationCorrection parseElevationCorrection(const std::string& text) {
  if (text == "auto") return ElevationCorrection::Auto;
  if (text == "etopo5-banks") return ElevationCorrection::EtopoBanks;
  if (text == "none") return ElevationCorrection::None;
  throw InputError("--elevation-correction: expected auto, etopo5-banks or none, got '" + text + "'");
}

void applyElevationCorrection(LatLonGrid& grid, ElevationCorrection mode, bool isDefault) {
  if (mode == ElevationCorrection::None || (mode == ElevationCorrection::Auto && !isDefault)) return;
  const LandMask& mask = defaultLandMask();
  const core::startup::Scope timed("data: shallow-bank correction");
  const BankCorrection c = correctShallowBanks(grid, &mask);
  char line[200];
  std::snprintf(line, sizeof line,
                "elevation '%s': ETOPO5's -10 m shallow-bank placeholder on %d plateaus, %zu cells "
                "near land set to %.1f-%.1f m (--elevation-correction none keeps it)",
                grid.name.c_str(), c.plateaus, c.cells, static_cast<double>(c.minDepthM),
                static_cast<double>(c.maxDepthM));
  log::info(line);
}

}  // namespace og::data
