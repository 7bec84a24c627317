#include "render/OpenSeaMap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include "core/Error.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

float OpenSeaMap::clearanceAt(double latitudeDeg, double longitudeDeg) const {
  const int row = std::clamp(static_cast<int>(std::floor(latitudeDeg + 90.0)), 0, kHeight - 1);
  const int col = std::clamp(static_cast<int>(std::floor(longitudeDeg + 180.0)), 0, kWidth - 1);
  return clearanceRad[static_cast<std::size_t>(row) * kWidth + static_cast<std::size_t>(col)];
}
namespace {
constexpr int kW = OpenSeaMap::kWidth;
constexpr int kH = OpenSeaMap::kHeight;
/// How far (cells) the clearance is measured: 30° of arc at most.
constexpr int kMaxRings = 30;

std::size_t index(int column, int row) {
  return static_cast<std::size_t>(row) * kW + static_cast<std::size_t>(column);
}

/// Marks every cell meeting the box [lonLo, lonHi] × [latLo, latHi] (degrees; longitudes wrap).
void markBox(std::vector<unsigned char>& blocked, double lonLo, double lonHi, double latLo, double latHi) {
  const int r0 = std::clamp(static_cast<int>(std::floor(latLo + 90.0)), 0, kH - 1);
  const int r1 = std::clamp(static_cast<int>(std::floor(latHi + 90.0)), 0, kH - 1);
  const int c0 = static_cast<int>(std::floor(lonLo + 180.0));
  const int c1 = std::min(static_cast<int>(std::floor(lonHi + 180.0)), c0 + kW - 1);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) blocked[index(((c % kW) + kW) % kW, r)] = 1;
}

/// Per row, the distance in columns (wrapping) to the nearest blocked cell, at most kMaxRings + 1.
std::vector<int> rowDistances(const std::vector<unsigned char>& blocked) {
  std::vector<int> g(blocked.size(), kMaxRings + 1);
  for (int r = 0; r < kH; ++r) {
    int* row = &g[index(0, r)];
    const unsigned char* b = &blocked[index(0, r)];
    for (int pass = 0; pass < 2; ++pass) {  // twice round, so the distance wraps the seam
      for (int c = 0; c < kW; ++c)
        row[c] = b[c] != 0 ? 0 : std::min(row[c], row[(c + kW - 1) % kW] + 1);
      for (int c = kW - 1; c >= 0; --c) row[c] = std::min(row[c], row[(c + 1) % kW] + 1);
    }
  }
  return g;
}
}  // namespace

std::vector<unsigned char> blockedByLayer(const data::LatLonGrid& layer, double minDepthM) {
  std::vector<unsigned char> blocked(static_cast<std::size_t>(kW) * kH, 0);
  if (!layer.wrapsLongitude) {  // a regional layer: left to the general parts
    std::fill(blocked.begin(), blocked.end(), 1);
    return blocked;
  }
  const auto normalized = [&](int c) {
    const double lon = std::fmod(layer.lon0Deg + c * layer.dLonDeg + 180.0, 360.0);
    return (lon < 0.0 ? lon + 360.0 : lon) - 180.0;
  };
  for (int r = 0; r < layer.height; ++r) {
    // A texel reaches one spacing each way through the bilinear filter; the outer rows reach
    // the poles (the texture clamps there).
    const double lat = layer.lat0Deg + r * layer.dLatDeg;
    const double latLo = r == 0 ? -90.0 : lat - layer.dLatDeg;
    const double latHi = r == layer.height - 1 ? 90.0 : lat + layer.dLatDeg;
    // Runs of texels that are not deep (NaN reads as -1 m on the GPU: blocked), one box a run:
    // the union of its texels' boxes, each from its own wrapped longitude as a box per texel
    // would be (the same cells, a few thousand boxes a row fewer).
    const float* row = &layer.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(layer.width)];
    for (int c = 0; c < layer.width; ++c) {
      if (static_cast<double>(row[c]) <= -minDepthM) continue;
      const int first = c;
      while (c + 1 < layer.width && !(static_cast<double>(row[c + 1]) <= -minDepthM)) ++c;
      const double lo = normalized(first) - layer.dLonDeg;
      double hi = normalized(c) + layer.dLonDeg;
      if ((c - first + 2) * layer.dLonDeg >= 360.0)
        hi = lo + 360.0;  // the whole circle (markBox stops after one turn)
      else if (normalized(c) < normalized(first))
        hi += 360.0;  // the run crosses the antimeridian
      markBox(blocked, lo, hi, latLo, latHi);
    }
  }
  return blocked;
}

void addBlockedByMask(const data::LandMask& mask, std::vector<unsigned char>& blocked, bool fineCells) {
  const auto bytesPerRow = static_cast<std::size_t>(mask.bytesPerRow());
  std::vector<std::uint8_t> withFine;
  if (fineCells && mask.hasFineLevel()) {
    withFine = mask.packedBits();
    const std::vector<std::uint8_t>& refined = mask.refinedBits();
    for (std::size_t i = 0; i < withFine.size() && i < refined.size(); ++i) withFine[i] |= refined[i];
  }
  const std::vector<std::uint8_t>& bits = withFine.empty() ? mask.packedBits() : withFine;
  const double cell = mask.cellDeg();
  std::vector<unsigned char> columns(kW);
  for (int r = 0; r < mask.height(); ++r) {
    const std::uint8_t* row = bits.data() + static_cast<std::size_t>(r) * bytesPerRow;
    std::fill(columns.begin(), columns.end(), 0);
    bool any = false;
    for (std::size_t b = 0; b < bytesPerRow; ++b) {
      if (b + 8 <= bytesPerRow) {  // skip 64 columns of water at a time
        std::uint64_t word = 0;
        std::memcpy(&word, row + b, sizeof word);
        if (word == 0) {
          b += 7;
          continue;
        }
      }
      if (row[b] == 0) continue;
      // The B-spline reaches 1.5 cells from a land cell's centre: two cells of margin.
      const double lonLo = mask.westDeg() + (8.0 * static_cast<double>(b) - 2.0) * cell + 180.0;
      const double lonHi = mask.westDeg() + (8.0 * static_cast<double>(b) + 10.0) * cell + 180.0;
      const int c1 = std::min(static_cast<int>(std::floor(lonHi)), static_cast<int>(std::floor(lonLo)) + kW - 1);
      for (int c = static_cast<int>(std::floor(lonLo)); c <= c1; ++c) columns[static_cast<std::size_t>(((c % kW) + kW) % kW)] = 1;
      any = true;
    }
    if (!any) continue;
    const double latLo = mask.southDeg() + (r - 2) * cell, latHi = mask.southDeg() + (r + 3) * cell;
    const int r0 = std::clamp(static_cast<int>(std::floor(latLo + 90.0)), 0, kH - 1);
    const int r1 = std::clamp(static_cast<int>(std::floor(latHi + 90.0)), 0, kH - 1);
    for (int cr = r0; cr <= r1; ++cr)
      for (int c = 0; c < kW; ++c) blocked[index(c, cr)] |= columns[static_cast<std::size_t>(c)];
  }
}

OpenSeaMap makeOpenSeaMap(std::vector<unsigned char> blocked) {
  if (blocked.size() != static_cast<std::size_t>(kW) * kH)
    throw InternalError("makeOpenSeaMap: the blocked cells must be 360 x 180");
  const std::vector<int> g = rowDistances(blocked);
  OpenSeaMap map;
  map.clearanceRad.assign(blocked.size(), 0.0f);
  constexpr double kDeg = std::numbers::pi / 180.0;
  for (int r = 0; r < kH; ++r)
    for (int c = 0; c < kW; ++c) {
      // Chebyshev distance to the nearest blocked cell: rows beyond the poles do not exist.
      int d = kMaxRings + 1;
      for (int rr = std::max(0, r - kMaxRings); rr <= std::min(kH - 1, r + kMaxRings); ++rr)
        d = std::min(d, std::max(g[index(c, rr)], std::abs(rr - r)));
      // The k rings of cells around this one are free; a point of the cell is at least k cells
      // of latitude from the box's parallels, and at least asin(cos φmax sin kΔ) from its
      // meridians (φmax the box's largest |latitude|). A box reaching a pole: 0.
      const int k = std::min(d, kMaxRings) - 1;
      if (k <= 0 || r - k < 0 || r + k > kH - 1) continue;
      const double south = -90.0 + (r - k), north = -90.0 + (r + k + 1);
      const double phiMax = std::max(std::abs(south), std::abs(north)) * kDeg;
      const double ring = k * OpenSeaMap::kCellDeg * kDeg;
      map.clearanceRad[index(c, r)] =
          static_cast<float>(std::min(ring, std::asin(std::cos(phiMax) * std::sin(ring))));
    }
  map.blocked = std::move(blocked);
  return map;
}

OpenSeaTexture::OpenSeaTexture(const OpenSeaMap& map) {
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  std::vector<float> texels(2 * map.clearanceRad.size(), 0.0f);
  for (std::size_t i = 0; i < map.clearanceRad.size(); ++i) {
    texels[2 * i] = map.clearanceRad[i];
    if (i < map.landClearanceRad.size()) texels[2 * i + 1] = map.landClearanceRad[i];
  }
  glTextureStorage2D(texture_.id(), 1, GL_RG32F, kW, kH);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, kW, kH, GL_RG, GL_FLOAT, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void OpenSeaTexture::bind() const { glBindTextureUnit(gl::kUnitOpenSea, texture_.id()); }

}  // namespace og::render
