#include "data/LandFractionMips.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace og::data {
namespace {

// For a byte of 8 cells of a row (bit k = cell k), the land cells of each pair (2k, 2k + 1):
// four counts of 0-2, 4 bits apart.
constexpr std::array<std::uint16_t, 256> kPairCounts = [] {
  std::array<std::uint16_t, 256> t{};
  for (unsigned b = 0; b < 256; ++b)
    for (unsigned k = 0; k < 4; ++k)
      t[b] = static_cast<std::uint16_t>(t[b] | ((((b >> (2 * k)) & 1u) + ((b >> (2 * k + 1)) & 1u)) << (4 * k)));
  return t;
}();

// Level 0's row `r` (cells of rows 2r and 2r + 1) as sums of land fine cells (64 a cell, ≤ 256 a
// texel): whole cells from the packed bits, four at a time, then each refined cell's own fine
// cells in place of its bit. `block` is the index of the first refined cell of row 2r (blocks
// run row-major) and moves past row 2r + 1's.
void levelZeroRow(const LandMask& mask, int r, std::size_t& block, std::vector<std::uint16_t>& sums) {
  const int stride = mask.bytesPerRow(), width = static_cast<int>(sums.size());
  std::fill(sums.begin(), sums.end(), std::uint16_t{0});
  for (int y = 2 * r; y < 2 * r + 2; ++y) {
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(stride);
    const std::uint8_t* row = mask.packedBits().data() + at;
    for (int b = 0; b < stride; ++b) {
      const unsigned counts = kPairCounts[row[b]];
      for (int k = 0; k < 4 && 4 * b + k < width; ++k)
        sums[static_cast<std::size_t>(4 * b + k)] = static_cast<std::uint16_t>(
            sums[static_cast<std::size_t>(4 * b + k)] + 64u * ((counts >> (4 * k)) & 15u));
    }
    if (!mask.hasFineLevel()) continue;
    const std::uint8_t* refined = mask.refinedBits().data() + at;
    for (int b = 0; b < stride; ++b)
      for (unsigned v = refined[b]; v != 0; v &= v - 1) {
        const int column = 8 * b + std::countr_zero(v);
        if (block >= mask.blocks().size() || column >= mask.width())
          throw InternalError("LandFractionMips: fewer blocks than refined cells, or refined padding bits");
        const int fine = std::popcount(mask.blocks()[block++]);
        auto& s = sums[static_cast<std::size_t>(column / 2)];
        s = static_cast<std::uint16_t>(s + fine - ((row[b] >> (column % 8)) & 1u) * 64);
      }
  }
}

}  // namespace

LandFractionMips::LandFractionMips(const LandMask& mask) : mask_(mask) {
  // (The GPU's texture spans 180° W ... 180° E and 90° S ... 90° N.)
  if (!mask.global() || mask.width() % 2 != 0 || mask.height() % 2 != 0 || std::abs(mask.westDeg() + 180.0) > 1e-9 ||
      std::abs(mask.southDeg() + 90.0) > 1e-9 || std::abs(mask.height() * mask.cellDeg() - 180.0) > 1e-6)
    throw InternalError("LandFractionMips: needs a global mask from 180° W and 90° S of even width and height, not " +
                        std::to_string(mask.width()) + " x " + std::to_string(mask.height()));
  Level first;
  first.width = mask.width() / 2;
  first.height = mask.height() / 2;
  first.bytes.resize(static_cast<std::size_t>(first.width) * static_cast<std::size_t>(first.height));
  std::vector<std::uint16_t> sums(static_cast<std::size_t>(first.width));
  std::size_t block = 0;
  for (int r = 0; r < first.height; ++r) {
    levelZeroRow(mask, r, block, sums);
    std::uint8_t* out = first.bytes.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(first.width);
    for (std::size_t c = 0; c < sums.size(); ++c) out[c] = static_cast<std::uint8_t>((sums[c] * 255u + 128u) / 256u);
  }
  if (block != mask.blocks().size()) throw InternalError("LandFractionMips: more blocks than refined cells");
  setBoxBits(first);
  levels_.push_back(std::move(first));
  // Each coarser level GL's next mip size (half, rounded down) and the rounded mean of the
  // texels under each of its texels (the GPU reads these bytes, so the CPU's lookups see what
  // it sees).
  while (levels() < kMaxLevels && levels_.back().width >= 2 && levels_.back().height >= 2) {
    Level coarse = halved(levels_.back());
    setBoxBits(coarse);
    levels_.push_back(std::move(coarse));
  }
}

namespace {

// Where coarse texel i of `coarse` over the same span as `fine` texels lies among them: the
// fine texels first ... first + weights.size() - 1 and how much of each it covers (summing to
// fine / coarse: 2 for an even side, a little over where halving rounded down).
struct Overlap {
  int first = 0;
  std::vector<double> weights;
};
Overlap overlapOf(int i, int fine, int coarse) {
  const double lo = static_cast<double>(i) * fine / coarse, hi = static_cast<double>(i + 1) * fine / coarse;
  Overlap o;
  o.first = static_cast<int>(std::floor(lo));
  for (int f = o.first; f < std::min(static_cast<int>(std::ceil(hi)), fine); ++f)
    o.weights.push_back(std::min(hi, f + 1.0) - std::max(lo, static_cast<double>(f)));
  return o;
}

}  // namespace

LandFractionMips::Level LandFractionMips::halved(const Level& fine) {
  // The area mean over each coarse texel's span: with even sides the 2 x 2 texels under it;
  // where a side is odd (the 2′ mask's 1350 × 675 at 16′, 675 × 337 at 32′) GL's texels still span the globe
  // evenly, so the mean weighs the fine rows by their overlap.
  Level coarse;
  coarse.width = fine.width / 2;
  coarse.height = fine.height / 2;
  coarse.bytes.resize(static_cast<std::size_t>(coarse.width) * static_cast<std::size_t>(coarse.height));
  std::vector<Overlap> columns;
  for (int x = 0; x < coarse.width; ++x) columns.push_back(overlapOf(x, fine.width, coarse.width));
  for (int y = 0; y < coarse.height; ++y) {
    const Overlap rows = overlapOf(y, fine.height, coarse.height);
    for (int x = 0; x < coarse.width; ++x) {
      const Overlap& cols = columns[static_cast<std::size_t>(x)];
      double sum = 0.0, area = 0.0;
      for (std::size_t j = 0; j < rows.weights.size(); ++j)
        for (std::size_t i = 0; i < cols.weights.size(); ++i) {
          const double w = rows.weights[j] * cols.weights[i];
          const std::size_t at = static_cast<std::size_t>(rows.first + static_cast<int>(j)) * static_cast<std::size_t>(fine.width) +
                                 static_cast<std::size_t>(cols.first + static_cast<int>(i));
          sum += w * fine.bytes[at];
          area += w;
        }
      coarse.bytes[static_cast<std::size_t>(y) * static_cast<std::size_t>(coarse.width) + static_cast<std::size_t>(x)] =
          static_cast<std::uint8_t>(std::floor(sum / area + 0.5));
    }
  }
  return coarse;
}

std::uint8_t LandFractionMips::texel(int level, int column, int row) const {
  const Level& l = levels_[static_cast<std::size_t>(level)];
  column = ((column % l.width) + l.width) % l.width;
  row = std::clamp(row, 0, l.height - 1);
  return l.bytes[static_cast<std::size_t>(row) * static_cast<std::size_t>(l.width) + static_cast<std::size_t>(column)];
}

std::size_t LandFractionMips::bytes() const {
  std::size_t n = 0;
  for (const Level& l : levels_) n += l.bytes.size();
  return n;
}

double LandFractionMips::weight(double footprintDeg) const {
  const double t = std::clamp(footprintDeg / mask_.cellDeg() - 1.0, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);  // smoothstep(1, 2, cells)
}

double LandFractionMips::levelOf(double footprintDeg) const {
  return std::log2(footprintDeg / (2.0 * mask_.cellDeg()));
}

// GL's LINEAR filter of one level: texel centres at (i + 0.5) / size of the texture's [0, 1],
// which spans the globe from 180° W and 90° S.
float LandFractionMips::bilinear(int level, double latitudeDeg, double longitudeDeg) const {
  const Level& l = levels_[static_cast<std::size_t>(level)];
  const double u = (longitudeDeg - mask_.westDeg()) / 360.0 * l.width - 0.5;
  const double v = (latitudeDeg - mask_.southDeg()) / 180.0 * l.height - 0.5;
  const double i0 = std::floor(u), j0 = std::floor(v), a = u - i0, b = v - j0;
  const int i = static_cast<int>(i0), j = static_cast<int>(j0);
  const double lower = (1.0 - a) * texel(level, i, j) + a * texel(level, i + 1, j);
  const double upper = (1.0 - a) * texel(level, i, j + 1) + a * texel(level, i + 1, j + 1);
  return static_cast<float>(((1.0 - b) * lower + b * upper) / 255.0);
}

float LandFractionMips::filtered(double latitudeDeg, double longitudeDeg, double lod) const {
  const int last = levels() - 1;
  lod = std::clamp(lod, 0.0, static_cast<double>(last));
  const int d = std::min(static_cast<int>(std::floor(lod)), last);
  const double f = lod - d;
  const double here = bilinear(d, latitudeDeg, longitudeDeg);
  if (d == last || f <= 0.0) return static_cast<float>(here);
  return static_cast<float>((1.0 - f) * here + f * static_cast<double>(bilinear(d + 1, latitudeDeg, longitudeDeg)));
}

float LandFractionMips::landFraction(double latitudeDeg, double longitudeDeg, double footprintDeg) const {
  const double m = weight(footprintDeg);
  if (m <= 0.0) return mask_.landFraction(latitudeDeg, longitudeDeg, footprintDeg);
  const auto f = static_cast<double>(filtered(latitudeDeg, longitudeDeg, levelOf(footprintDeg)));
  if (m >= 1.0) return static_cast<float>(f);
  return static_cast<float>((1.0 - m) * static_cast<double>(mask_.landFraction(latitudeDeg, longitudeDeg, footprintDeg)) + m * f);
}

void LandFractionMips::setBoxBits(Level& l) {
  l.wordsPerRow = (l.width + 63) / 64;
  const std::size_t words = static_cast<std::size_t>(l.wordsPerRow) * static_cast<std::size_t>(l.height);
  l.notLand.assign(words, 0);
  l.notWater.assign(words, 0);
  for (int r = 0; r < l.height; ++r)
    for (int c = 0; c < l.width; ++c) {
      const std::uint8_t b = l.bytes[static_cast<std::size_t>(r) * static_cast<std::size_t>(l.width) + static_cast<std::size_t>(c)];
      const std::size_t w = static_cast<std::size_t>(r) * static_cast<std::size_t>(l.wordsPerRow) + static_cast<std::size_t>(c / 64);
      const std::uint64_t bit = std::uint64_t{1} << (c % 64);
      if (b < kLandByte) l.notLand[w] |= bit;
      if (b > kWaterByte) l.notWater[w] |= bit;
    }
}

namespace {

// Whether any of bits c0 ... c1 (within the row) of a row of words is set.
bool anyBits(const std::uint64_t* row, int c0, int c1) {
  for (int w = c0 / 64; w <= c1 / 64; ++w) {
    const int lo = std::max(c0 - 64 * w, 0), hi = std::min(c1 - 64 * w, 63);
    const std::uint64_t used = (hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (hi + 1)) - 1u) & ~((std::uint64_t{1} << lo) - 1u);
    if ((row[w] & used) != 0) return true;
  }
  return false;
}

}  // namespace

LandMaskPyramid::Content LandFractionMips::boxContent(double latLoDeg, double latHiDeg, double lonLoDeg,
                                                      double lonHiDeg, double lodLo, double lodHi) const {
  const int last = levels() - 1;
  const int d0 = std::min(static_cast<int>(std::floor(std::clamp(lodLo, 0.0, static_cast<double>(last)))), last);
  const int d1 = std::min(static_cast<int>(std::floor(std::clamp(lodHi, 0.0, static_cast<double>(last)))) + 1, last);
  bool land = true, water = true;
  for (int d = d0; d <= d1 && (land || water); ++d) {
    const Level& l = levels_[static_cast<std::size_t>(d)];
    // The texels a bilinear lookup at any point of the box reads: floor(u) ... floor(u) + 1.
    const auto column = [&](double lon) { return static_cast<int>(std::floor((lon - mask_.westDeg()) / 360.0 * l.width - 0.5)); };
    const auto row = [&](double lat) { return static_cast<int>(std::floor((lat - mask_.southDeg()) / 180.0 * l.height - 0.5)); };
    const int c0 = column(lonLoDeg), c1 = std::min(column(lonHiDeg) + 1, c0 + l.width - 1);
    const int r0 = std::max(row(latLoDeg), 0), r1 = std::min(row(latHiDeg) + 1, l.height - 1);
    // Each row's columns as at most two runs (the wrap), 64 texels a word.
    const int first = ((c0 % l.width) + l.width) % l.width, count = c1 - c0 + 1;
    const int run0 = std::min(count, l.width - first);
    if (r0 > r1 || count <= 0) return LandMaskPyramid::Content::Both;  // (no texel: nothing known)
    for (int r = r0; r <= r1 && (land || water); ++r) {
      const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(l.wordsPerRow);
      for (const std::vector<std::uint64_t>* bits : {&l.notLand, &l.notWater}) {
        bool& still = bits == &l.notLand ? land : water;
        if (!still) continue;
        const std::uint64_t* rowBits = bits->data() + at;
        still = !anyBits(rowBits, first, first + run0 - 1) && (count == run0 || !anyBits(rowBits, 0, count - run0 - 1));
      }
    }
  }
  return land ? LandMaskPyramid::Content::Land : water ? LandMaskPyramid::Content::Water : LandMaskPyramid::Content::Both;
}

}  // namespace og::data
