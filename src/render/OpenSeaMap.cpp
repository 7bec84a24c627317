#include "render/OpenSeaMap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include <glm/gtc/packing.hpp>

#include "core/Error.hpp"
#include "gl/ShaderContract.hpp"

namespace og::render {

namespace {
constexpr int kW = OpenSeaMap::kWidth;
constexpr int kH = OpenSeaMap::kHeight;
constexpr double kPerDeg = OpenSeaMap::kCellsPerDeg;

std::size_t index(int column, int row) {
  return static_cast<std::size_t>(row) * kW + static_cast<std::size_t>(column);
}
/// The cell row of a latitude, the (unwrapped) cell column of a longitude, degrees.
int rowOf(double latitudeDeg) { return static_cast<int>(std::floor((latitudeDeg + 90.0) * kPerDeg)); }
int columnOf(double longitudeDeg) { return static_cast<int>(std::floor((longitudeDeg + 180.0) * kPerDeg)); }
int wrapped(int column) { return ((column % kW) + kW) % kW; }

/// Marks every cell in columns c0..c1 (unwrapped, at most one turn) meeting latitudes
/// [latLo, latHi] (degrees).
void markBox(std::vector<unsigned char>& blocked, int c0, int c1, double latLo, double latHi) {
  const int r0 = std::clamp(rowOf(latLo), 0, kH - 1);
  const int r1 = std::clamp(rowOf(latHi), 0, kH - 1);
  c1 = std::min(c1, c0 + kW - 1);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) blocked[index(wrapped(c), r)] = 1;
}
}  // namespace

float OpenSeaMap::clearanceAt(double latitudeDeg, double longitudeDeg) const {
  const int row = std::clamp(rowOf(latitudeDeg), 0, kHeight - 1);
  const int col = std::clamp(columnOf(longitudeDeg), 0, kWidth - 1);
  return clearanceRad[index(col, row)];
}

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
      // (The columns of its first and last texels' own boxes, so that no rounding of an
      // unwrapped longitude marks a cell no texel's box meets.)
      const int c0 = columnOf(normalized(first) - layer.dLonDeg);
      int c1 = columnOf(normalized(c) + layer.dLonDeg);
      if ((c - first + 2) * layer.dLonDeg >= 360.0)
        c1 = c0 + kW - 1;  // the whole circle
      else if (normalized(c) < normalized(first))
        c1 += kW;  // the run crosses the antimeridian
      markBox(blocked, c0, c1, latLo, latHi);
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
  // Columns as bits, 64 a word: a mask row's reach into each cell row it meets, OR-ed by words.
  constexpr std::size_t kWords = (kW + 63) / 64;
  std::vector<std::uint64_t> rowBits(kWords * static_cast<std::size_t>(kH), 0), columns(kWords);
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
      const std::size_t first = b;  // a run of bytes with land
      while (b + 1 < bytesPerRow && row[b + 1] != 0) ++b;
      // The B-spline reaches 1.5 cells from a land cell's centre: two cells of margin.
      const int c0 = columnOf(mask.westDeg() + (8.0 * static_cast<double>(first) - 2.0) * cell);
      const int c1 = std::min(columnOf(mask.westDeg() + (8.0 * static_cast<double>(b) + 10.0) * cell), c0 + kW - 1);
      for (int c = c0; c <= c1; ++c) {
        const auto w = static_cast<std::size_t>(wrapped(c));
        columns[w / 64] |= std::uint64_t{1} << (w % 64);
      }
      any = true;
    }
    if (!any) continue;
    const int r0 = std::clamp(rowOf(mask.southDeg() + (r - 2) * cell), 0, kH - 1);
    const int r1 = std::clamp(rowOf(mask.southDeg() + (r + 3) * cell), 0, kH - 1);
    for (int cr = r0; cr <= r1; ++cr)
      for (std::size_t w = 0; w < kWords; ++w) rowBits[static_cast<std::size_t>(cr) * kWords + w] |= columns[w];
  }
  for (int cr = 0; cr < kH; ++cr) {
    const std::uint64_t* bitRow = &rowBits[static_cast<std::size_t>(cr) * kWords];
    for (int c = 0; c < kW; ++c)
      if ((bitRow[c / 64] >> (c % 64)) & 1u) blocked[index(c, cr)] = 1;
  }
}

std::vector<std::uint8_t> chessboardDistances(const std::vector<unsigned char>& blocked, int cap) {
  if (cap < 0 || cap > 255) throw InternalError("chessboardDistances: the cap must be 0..255");
  const auto top = static_cast<std::uint8_t>(cap);
  std::vector<std::uint8_t> d(blocked.size());
  for (std::size_t i = 0; i < blocked.size(); ++i) d[i] = blocked[i] != 0 ? 0 : top;
  const auto plusOne = [top](std::uint8_t v) { return static_cast<std::uint8_t>(std::min<int>(v + 1, top)); };
  // Forward: from the row below (its three neighbours) and from the left; backward: from the
  // row above and from the right. A shortest 8-connected path can always be ordered so that
  // each pass takes its steps in turn.
  for (int pass = 0; pass < 2; ++pass) {
    for (int n = 0; n < kH; ++n) {
      const int r = pass == 0 ? n : kH - 1 - n, before = pass == 0 ? r - 1 : r + 1;
      std::uint8_t* row = &d[index(0, r)];
      if (before >= 0 && before < kH) {
        const std::uint8_t* near = &d[index(0, before)];
        row[0] = std::min({row[0], plusOne(near[kW - 1]), plusOne(near[0]), plusOne(near[1])});
        for (int c = 1; c < kW - 1; ++c)
          row[c] = std::min({row[c], plusOne(near[c - 1]), plusOne(near[c]), plusOne(near[c + 1])});
        row[kW - 1] = std::min({row[kW - 1], plusOne(near[kW - 2]), plusOne(near[kW - 1]), plusOne(near[0])});
      }
      // Along the row, round past the seam until nothing changes (at most twice round).
      for (int k = 1; k < 2 * kW; ++k) {
        const int c = pass == 0 ? k % kW : kW - 1 - k % kW, from = pass == 0 ? (c + kW - 1) % kW : (c + 1) % kW;
        const std::uint8_t v = plusOne(row[from]);
        if (v < row[c]) row[c] = v;
        else if (k >= kW) break;  // past the seam: the rest holds already
      }
    }
  }
  return d;
}

static_assert(OpenSeaMap::kMaxRings + 1 <= 255, "chessboardDistances holds distances in bytes");

OpenSeaMap makeOpenSeaMap(std::vector<unsigned char> blocked) {
  if (blocked.size() != static_cast<std::size_t>(kW) * kH)
    throw InternalError("makeOpenSeaMap: the blocked cells must be OpenSeaMap::kWidth x kHeight");
  constexpr int kMaxRings = OpenSeaMap::kMaxRings;
  const std::vector<std::uint8_t> d = chessboardDistances(blocked, kMaxRings + 1);
  OpenSeaMap map;
  map.clearanceRad.assign(blocked.size(), 0.0f);
  constexpr double kDeg = std::numbers::pi / 180.0;
  std::vector<float> ofRings(kMaxRings + 1);  // a row's radius by free rings (-1: not yet)
  for (int r = 0; r < kH; ++r) {
    std::fill(ofRings.begin(), ofRings.end(), -1.0f);
    for (int c = 0; c < kW; ++c) {
      // The k rings of cells around this one are free; a point of the cell is at least k cells
      // of latitude from the box's parallels, and at least asin(cos φmax sin kΔ) from its
      // meridians (φmax the box's largest |latitude|). A box reaching a pole: 0.
      const int k = std::min<int>(d[index(c, r)], kMaxRings) - 1;
      if (k <= 0 || r - k < 0 || r + k > kH - 1) continue;
      float& radius = ofRings[static_cast<std::size_t>(k)];
      if (radius < 0.0f) {
        const double south = -90.0 + (r - k) * OpenSeaMap::kCellDeg, north = -90.0 + (r + k + 1) * OpenSeaMap::kCellDeg;
        const double phiMax = std::max(std::abs(south), std::abs(north)) * kDeg;
        const double ring = k * OpenSeaMap::kCellDeg * kDeg;
        radius = static_cast<float>(std::min(ring, std::asin(std::cos(phiMax) * std::sin(ring))));
      }
      map.clearanceRad[index(c, r)] = radius;
    }
  }
  map.blocked = std::move(blocked);
  return map;
}

OpenSeaMap makeRendererOpenSeaMap(std::vector<unsigned char> layerBlocked, const data::LandMask* mask) {
  if (mask == nullptr) return makeOpenSeaMap(std::move(layerBlocked));
  std::vector<unsigned char> fine(layerBlocked.size(), 0);
  addBlockedByMask(*mask, layerBlocked);
  addBlockedByMask(*mask, fine, true);
  OpenSeaMap map = makeOpenSeaMap(std::move(layerBlocked));
  map.landClearanceRad = makeOpenSeaMap(std::move(fine)).clearanceRad;
  return map;
}

std::vector<std::uint16_t> openSeaTexels(const OpenSeaMap& map) {
  // The nearest half float, one step down where that rounded up (for a positive half the next
  // smaller value is the bits less one). A row's radii take few values, in runs: the last
  // conversion is kept.
  float lastRadius = 0.0f;
  std::uint16_t lastHalf = 0;
  const auto half = [&](float radius) {
    if (radius != lastRadius) {
      lastRadius = radius;
      lastHalf = glm::packHalf1x16(radius);
      if (glm::unpackHalf1x16(lastHalf) > radius) --lastHalf;
    }
    return lastHalf;
  };
  std::vector<std::uint16_t> texels(2 * map.clearanceRad.size(), 0);
  for (std::size_t i = 0; i < map.clearanceRad.size(); ++i) {
    texels[2 * i] = half(map.clearanceRad[i]);
    if (i < map.landClearanceRad.size()) texels[2 * i + 1] = half(map.landClearanceRad[i]);
  }
  return texels;
}

OpenSeaTexture::OpenSeaTexture(const std::vector<std::uint16_t>& texels) {
  if (texels.size() != 2 * static_cast<std::size_t>(kW) * kH)
    throw InternalError("OpenSeaTexture: the texels must be OpenSeaMap::kWidth x kHeight pairs");
  texture_ = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(texture_.id(), 1, GL_RG16F, kW, kH);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, kW, kH, GL_RG, GL_HALF_FLOAT, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void OpenSeaTexture::bind() const { glBindTextureUnit(gl::kUnitOpenSea, texture_.id()); }

}  // namespace og::render
