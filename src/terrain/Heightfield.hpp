#pragma once
// The terrain's height function: the elevation layer (bilinear) plus deterministic fractal
// detail below the layer's resolution. A pure function of the geodetic position, so tiles of any
// level that share a vertex position get bit-identical heights (crack-free seams).
//
// The detail's octaves (shaders/terrain/detail.glsl, compiled here as C++) go from two layer
// cells down to kDetailShortestM in the heights; the normals go on down to kNormalShortestM,
// the mesh's vertex normals carrying the octaves it resolves and the fragment shader the finer
// ones, as many as each pixel's footprint allows.
#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <utility>

#include "data/LandMask.hpp"
#include "data/LatLonGrid.hpp"

namespace og::terrain {

/// The detail's octave ladder for a layer: octave k has wavelength longestM / 2^k and weight
/// detailOctaveWeight(k) / norm (terrain/detail.glsl).
struct DetailOctaves {
  double longestM = 0.0;
  int heightCount = 0;  ///< octaves in the heights (wavelength >= kDetailShortestM)
  int normalCount = 0;  ///< octaves in the normals (wavelength >= kNormalShortestM)
  double norm = 1.0;    ///< sum of the height octaves' weights
  static constexpr int kMaxOctaves = 24;
  /// Per octave (the first normalCount; Heightfield fills them), what detailSum would otherwise
  /// recompute at every point: detailOctaveWeight(k) (before normalisation) and the lattice's
  /// scale on the unit sphere, a / wavelengthM(k).
  std::array<double, kMaxOctaves> weight{}, latticeScale{};
  [[nodiscard]] double wavelengthM(int k) const;
  /// The first octave finer than `wavelengthM` (the number of octaves at least that long).
  [[nodiscard]] int countAtLeast(double wavelengthM) const;
};

/// Height and surface normal at a point.
struct HeightSample {
  double heightM = 0.0;         ///< above mean sea level, detail included
  double detailAmplitudeM = 0;  ///< the detail's local amplitude in the heights (scales its normalised sum)
  double shadingAmplitudeM = 0; ///< the same in the normals (vertex and pixel), without the 80 % bound
  glm::dvec3 normal{0.0};       ///< unit, ECEF axes
};

class Heightfield {
 public:
  /// Shares the layer (no copy: the default's 9.3 million cells are 37 MB). NaN (no data) reads
  /// as 1 m below sea level (sea), as the globe pass does.
  explicit Heightfield(std::shared_ptr<const data::LatLonGrid> layer);
  /// Keeps the layer (moved or copied in).
  explicit Heightfield(data::LatLonGrid layer)
      : Heightfield(std::make_shared<const data::LatLonGrid>(std::move(layer))) {}

  /// Height above mean sea level in metres (negative = depth) at a geodetic position (degrees),
  /// detail included.
  [[nodiscard]] double heightM(double latitudeDeg, double longitudeDeg) const;
  /// Height plus the normal of the layer (central differences `stepDeg` either way) tilted by
  /// the detail's first `normalOctaves` octaves (analytic gradient). The height is the same as
  /// heightM() bit for bit.
  [[nodiscard]] HeightSample sample(double latitudeDeg, double longitudeDeg, int normalOctaves,
                                    double stepDeg) const;
  /// sample() in two halves, for a caller that may not need the normal (a tile the sea
  /// covers): the height and amplitudes (normal left zero) with the detail's gradient of its
  /// first `normalOctaves` octaves in `*detailGradient`, then the normal from them.
  [[nodiscard]] HeightSample sampleHeight(double latitudeDeg, double longitudeDeg, int normalOctaves,
                                          glm::dvec3* detailGradient) const;
  [[nodiscard]] glm::dvec3 normalAt(double latitudeDeg, double longitudeDeg, double stepDeg,
                                    const glm::dvec3& detailGradient, double shadingAmplitudeM) const;
  /// The layer alone (bilinear, no detail), metres; for a global layer coarser than the GSHHG
  /// land mask (data::LandMask::refines), constrained to it so its coast is the mask's.
  [[nodiscard]] double layerHeightM(double latitudeDeg, double longitudeDeg) const;
  /// The detail's amplitude at a point, m (the scale of its normalised sum). On land,
  /// calibrated so the octaves add the slope variance the self-affine law puts below the
  /// layer's cell (calibratedRmsSlope, docs/terrain.md "Calibration of the detail"); under the
  /// sea 2.5 × the layer's relief across two cells (the coast's floor). At least 3 % of |h|
  /// and at most 80 % of it, so detail never crosses sea level.
  [[nodiscard]] double detailAmplitudeM(double latitudeDeg, double longitudeDeg) const;
  /// The detail's amplitude in the normals (the tile's vertex normals and the pixels' finer
  /// octaves alike, so levels meet without a shading step): detailAmplitudeM without the 80 %
  /// bound (it guards the coastline's heights), so low valleys near the sea keep the law's
  /// slopes.
  [[nodiscard]] double detailShadingAmplitudeM(double latitudeDeg, double longitudeDeg) const;
  /// RMS of the layer's height differences to its four neighbours one cell (cellM()) away,
  /// m: its structure function at lag Δ, σ(Δ).
  [[nodiscard]] double layerRmsDifferenceM(double latitudeDeg, double longitudeDeg) const;
  /// The ground's RMS slope (one horizontal component, tan) at scale `scaleM` ≤ the cell
  /// where the layer's RMS difference is `rmsDifferenceM`: G (σ(Δ)/Δ) (L/Δ)^(H-1) with
  /// H = detailHurst() and G = kLayerSlopeGain.
  [[nodiscard]] double calibratedRmsSlope(double rmsDifferenceM, double scaleM) const;

  /// What the layer's cell averaging smooths away, as a factor on its RMS slope at its own
  /// cell: calibrated so the law meets published 90 m slopes of steep ranges from ETOPO5
  /// (docs/terrain.md, "Calibration of the detail").
  static constexpr double kLayerSlopeGain = 3.3;
  /// RMS of one horizontal component of a ridged octave's gradient per unit of its amplitude,
  /// in lattice units (terrain/detail.glsl's detailRidged on the sphere; measured, tested).
  static constexpr double kRidgedSlopeRms = 1.41;

  /// Shortest wavelength of the procedural detail in the heights, m.
  static constexpr double kDetailShortestM = 40.0;
  /// Shortest wavelength of the detail in the shading normals, m.
  static constexpr double kNormalShortestM = 2.5;

  /// True when the land mask decides the coast (a global layer coarser than it): land is then
  /// never below sea level (layerHeightM), nor water above it.
  [[nodiscard]] bool coastFromMask() const { return mask_ != nullptr; }
  /// The land mask that decides the coast, or nullptr (coastFromMask).
  [[nodiscard]] const data::LandMask* landMask() const { return mask_; }
  [[nodiscard]] const DetailOctaves& octaves() const { return octaves_; }
  [[nodiscard]] const data::LatLonGrid& layer() const { return *layer_; }
  [[nodiscard]] const std::shared_ptr<const data::LatLonGrid>& sharedLayer() const { return layer_; }
  /// The layer's cell size, m (north-south).
  [[nodiscard]] double cellM() const { return cellM_; }

 private:
  /// detailAmplitudeM for a layer height `h` already read there.
  [[nodiscard]] double detailAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const;
  [[nodiscard]] double detailShadingAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const;
  /// detailAmplitudeM from the shading's amplitude there (what bounds it on land).
  [[nodiscard]] static double detailAmplitudeFromShadingM(double h, double shadingAmplitudeM);
  [[nodiscard]] double seaDetailAmplitudeM(double latitudeDeg, double longitudeDeg, double h) const;
  [[nodiscard]] double layerRmsDifferenceM(double latitudeDeg, double longitudeDeg, double h) const;

  std::shared_ptr<const data::LatLonGrid> layer_;
  const data::LandMask* mask_ = nullptr;  ///< decides the coast when the layer is coarser
  double cellM_ = 0.0;
  DetailOctaves octaves_;
  double amplitudePerRms_ = 0.0;  ///< land detail amplitude per metre of σ(Δ)
};

/// The detail's Hurst exponent: its octaves' amplitudes fall as wavelength^H (gain 2^-H per
/// octave, terrain/detail.glsl's DETAIL_GAIN = 0.6, H = 0.737).
double detailHurst();

/// The detail's normalised sum (in [-1, 1]) at a point of the unit sphere, over octaves
/// [0, count), and the gradient (per unit of the sphere's coordinates) of its first
/// `gradientOctaves` octaves.
double detailSum(const DetailOctaves& o, const glm::dvec3& unitUp, int count, int gradientOctaves,
                 glm::dvec3* gradient);

/// The octave's lattice coordinate of a point of the unit sphere: unitUp · a / wavelength plus
/// the octave's offset (what the fragment shader continues from the eye's).
glm::dvec3 detailLatticePoint(const DetailOctaves& o, int k, const glm::dvec3& unitUp);

}  // namespace og::terrain
