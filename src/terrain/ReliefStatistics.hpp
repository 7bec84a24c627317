#pragma once
// Slope statistics of an elevation layer and of the procedural detail, per region and scale:
// what the detail is calibrated against (docs/terrain.md, "Calibration of the detail").
//
// Real relief is close to self-affine: the RMS height difference over a horizontal distance
// L grows like L^H (the structure function, Hurst exponent H ≈ 0.7; Gagnon, Lovejoy &
// Schertzer 2006, "Multifractal earth topography", Nonlin. Processes Geophys. 13, 541), so
// the RMS slope at scale L, σ(L) / L, grows like L^(H-1) as L shrinks.
#include <glm/glm.hpp>

#include "data/LatLonGrid.hpp"
#include "terrain/Heightfield.hpp"

namespace og::terrain {

/// A latitude/longitude box, degrees (west < east, no antimeridian crossing).
struct RegionBox {
  double southDeg = 0.0, northDeg = 0.0, westDeg = 0.0, eastDeg = 0.0;
};

/// Height differences of a layer at one lag.
struct LagStatistics {
  double lagM = 0.0;         ///< the lag, m
  double rmsDiffM = 0.0;     ///< RMS height difference over the lag (N-S and E-W pairs), m
  /// RMS directional slope at that scale, rmsDiffM / lagM (dimensionless, tan).
  [[nodiscard]] double rmsSlope() const { return lagM > 0.0 ? rmsDiffM / lagM : 0.0; }
};

/// The structure function of `layer` (bilinear samples) in `box` at a lag of `lagM` metres,
/// from points on a grid of the layer's row spacing; points whose pairs leave the layer or
/// touch no-data are skipped. A pair of N-S and one of E-W per point.
LagStatistics layerLagStatistics(const data::LatLonGrid& layer, const RegionBox& box, double lagM);

/// Mean slope of `layer` in `box` as GIS tools compute it from a DEM: the gradient magnitude
/// from central differences over one cell either way (3×3 window), averaged; tan of the slope.
double layerMeanGradient(const data::LatLonGrid& layer, const RegionBox& box);

/// The slope the detail's octaves of wavelength ≥ `scaleM` give the ground (layer excluded),
/// over `samples` points spread over `box`: RMS of one horizontal component of the detail's
/// height gradient (amplitude included), dimensionless (tan).
double detailRmsSlope(const Heightfield& heights, const RegionBox& box, double scaleM, int samples);

}  // namespace og::terrain
