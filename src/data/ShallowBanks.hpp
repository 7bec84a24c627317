#pragma once
// ETOPO5's shallow-bank placeholder and its correction (docs/coast.md, "The banks' depth").
//
// ETOPO5 (NOAA NGDC 1988; its sea floor from the US Navy's DBDB5, gridded from contour charts)
// stores large shallow areas as flat plateaus at exactly -10 m: no flag marks them, but -10 m
// holds 58 872 of its cells against ~4 500 for each depth from -1 to -30 m, in 8-connected
// patches of up to ~1 400 cells (the Great Bahama Bank, the Queensland coast inside the Great
// Barrier Reef, the Amazon and East Siberian shelves, Antarctic ice shelves, patches of outer
// shelf such as off Patagonia). ETOPO20 (the embedded default) is ETOPO5 averaged to 20', so
// the plateaus' inner cells are exactly -10 m there too and their rims mixtures.
//
// The correction replaces a plateau's cells near land by a depth rising from the shore:
// d = min(d_placeholder, d_shore + g s), s the distance to the nearest land (GSHHG mask or the
// layer's own land) through the plateau, d_shore = 1 m, g = 0.1 m/km: 1 m at the beach, ~5 m
// 40 km out, the placeholder's 10 m from 90 km on. Over the Great Bahama Bank west of Andros
// that spans the 2-7 m the charts give (NASA's caption of the bank from orbit: "less than
// 9 m (30 ft) deep"); plateaus far from land (outer shelves) keep their 10 m. A plausible field,
// not soundings.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "data/LatLonGrid.hpp"

namespace og::data {

class LandMask;

/// ETOPO5's placeholder depth, m.
inline constexpr float kEtopoPlaceholderM = -10.0f;
/// The corrected depth at the shore, m, and its rise with the distance from land, m per km.
inline constexpr double kBankShoreDepthM = 1.0;
inline constexpr double kBankDepthPerKm = 0.1;
/// A patch of placeholder cells smaller than this is taken for real relief, km².
inline constexpr double kPlateauMinAreaKm2 = 2500.0;

/// A connected patch of cells at exactly kEtopoPlaceholderM that is a placeholder plateau.
struct Plateau {
  std::vector<std::size_t> cells;  ///< indices into LatLonGrid::values
  double areaKm2 = 0.0;
  double centreLatDeg = 0.0, centreLonDeg = 0.0;  ///< mean of the cells' centres
};

/// The placeholder plateaus of `grid`: 8-connected patches (across the seam for a global grid)
/// of cells at exactly kEtopoPlaceholderM covering at least kPlateauMinAreaKm2, holding at least
/// one 2 x 2 block (a plateau, not a contour line of a slope) and not a terrace of a gentle
/// slope (fewer than half of the cells around it at -9 or -11 m). Real -10 m cells in varied
/// relief are isolated or a line and are left out.
std::vector<Plateau> findPlaceholderPlateaus(const LatLonGrid& grid);

/// What correctShallowBanks changed.
struct BankCorrection {
  int plateaus = 0;        ///< plateaus found
  std::size_t cells = 0;   ///< cells made shallower
  float minDepthM = 0.0f, maxDepthM = 0.0f;  ///< range of the new depths (positive m)
};

/// Replaces the placeholder plateaus of `grid` (and the shallower rim cells mixed with them,
/// above -10 m and below 0) near land by the shore-distance depth field above, land being the
/// layer's cells above 0 m and, with `mask`, any GSHHG land in a cell. Marks the changed cells
/// in grid.keepDepth (1) so that the land mask does not deepen them again
/// (LandMask::constrainHeightM). Deterministic; O(cells of the plateaus).
BankCorrection correctShallowBanks(LatLonGrid& grid, const LandMask* mask);

/// How an elevation layer is corrected on load (--elevation-correction).
enum class ElevationCorrection {
  Auto,        ///< the embedded default (ETOPO5-derived) corrected, files as they are
  EtopoBanks,  ///< the shallow-bank correction on any layer
  None,        ///< no correction, even of the default
};
/// Parses "auto", "etopo5-banks" or "none"; og::InputError otherwise.
ElevationCorrection parseElevationCorrection(const std::string& text);

/// Applies `mode` to `grid` (`isDefault`: the embedded layer) with the default GSHHG mask and
/// logs one line saying what changed.
void applyElevationCorrection(LatLonGrid& grid, ElevationCorrection mode, bool isDefault);

}  // namespace og::data
