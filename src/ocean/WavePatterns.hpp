#pragma once
// The sea as FFT wave patterns (Dupuy & Bruneton 2012, §2; Tessendorf 2001): kPatternCount
// periodic tiles of different sizes (periods not multiples of each other), each holding one
// radial band of the Elfouhaily spectrum, so together they span 2 cm .. 5 km waves. Each tile
// is a grid of fftSize² Fourier modes; the GPU turns them into height, choppy displacement,
// slopes and Jacobian terms every frame (render/OceanPatterns, shaders/ocean/fft_*.comp).
//
// Direction: every pattern exists in kPatternSets spectra, one for a wind along the tile's
// +x axis and one for a wind at 45° to it. Rotating a tile's lookup by quarter turns is exact
// on its periodic lattice, so the sets give 8 direction bins 45° apart; the shaders blend the
// two bins around the local wind (docs/ocean.md), never rotating by a varying angle (which
// would stretch waves in proportion to the distance from the rotation's centre).
//
// Local wind speed: the spectra are made once for the strongest wind of the scene
// (referenceWindMs). Elsewhere each band is scaled so that its height and slope variances are
// those of the local wind (PatternTables) — bands stay put, amplitudes follow the wind.
//
// This library has no GL: it makes the initial spectra and the statistics both the GPU and
// the CPU checks use. Units: metres, rad/m, rad/s, m/s.
#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "ocean/Spectrum.hpp"

namespace og::ocean {

inline constexpr int kPatternCount = 5;
inline constexpr int kPatternSets = 2;
/// The shortest wave of a pattern spans this many texels (bilinear filtering and the first
/// mip level keep it); shorter waves belong to the next, finer pattern.
inline constexpr double kTexelsPerShortestWave = 4.0;
/// Shortest wavelength the finest pattern resolves, m; the rest is the BRDF's tail.
inline constexpr double kShortestPatternWaveM = 0.02;
/// Wave phases repeat with this period (angular frequencies are rounded to multiples of
/// 2 pi / period, Tessendorf 2001 §4.5), so the GPU receives the time modulo the period, exact.
inline constexpr double kWaveRepeatPeriodS = 4096.0;

struct WavePatternParams {
  /// The strongest 10 m wind the patterns must hold, m/s, [0.5, 50] (clamped to >= 1).
  double referenceWindMs = 10.0;
  /// Modes per tile side: a power of two in [16, 1024].
  int fftSize = 128;
  /// Tile sizes, m, largest first, each smaller than the one before; 0 = defaultPatternSizes.
  std::array<double, kPatternCount> sizesM{};
  /// Choppiness lambda_i of Eq. 1 (Dupuy 2012) per pattern, [0, 2]: the weight of the pattern
  /// in the whitecaps' Jacobian and, from kDisplacedChoppiness up, its horizontal displacement.
  /// Whitecaps come from the breaking of the energetic waves near the spectral peak: full chop
  /// on the two longest patterns (waves > 17 m). The short waves riding on them break the foam
  /// patches' outlines up but hardly depend on the wind (with full weight the coverage would
  /// grow far too slowly with the wind to follow Monahan 1980): a quarter on the 0.2-17 m
  /// waves, none on the centimetric ripples.
  std::array<double, kPatternCount> choppiness{1.0, 1.0, 0.25, 0.25, 0.0};
  std::uint64_t seed = 1;  ///< the random amplitudes and phases are reproducible from it
};

/// Patterns with at least this choppiness are displaced horizontally (Dupuy 2012 Eq. 1); below
/// it the displacement would be a fraction of a grid cell wherever the pattern is geometry.
inline constexpr double kDisplacedChoppiness = 0.5;
/// Whether pattern `pattern` of `p` is displaced horizontally (kDisplacedChoppiness).
[[nodiscard]] bool patternDisplaced(const WavePatternParams& p, int pattern);
/// Complex fields the FFTs of the first `patternCount` patterns of one direction set take, in
/// pattern order (h + i dh/dx, dh/dy + i t, and Dx + i Dy for displaced patterns: 2 or 3 each);
/// pattern i's first is fftSlots(p, i) (shaders/ocean/fft_common.glsl, ocean::PatternSynthesis).
[[nodiscard]] int fftSlots(const WavePatternParams& p, int patternCount);

/// Tile sizes for fftSize modes: the largest 4983 m (waves up to ~2.5 x the peak of a 45 m/s
/// wind), the finest such that its shortest wave is kShortestPatternWaveM, and the ratios
/// between them equal and irrational, so no period divides another.
std::array<double, kPatternCount> defaultPatternSizes(int fftSize);

/// Spatial statistics of one pattern of one set, time-averaged, at the reference wind.
struct PatternStats {
  double heightVarianceM2 = 0.0;
  /// Slope variance along (up) and across (cross) the set's wind.
  SlopeVariance slope;
  /// Variance of the pattern's Jacobian term j = lambda (a + b), a = dDx/dx, b = dDy/dy: the
  /// linear part of Dupuy 2012 Eq. 7. Its quadratic part lambda² (a b - c²) is left out: its
  /// mean is zero, its variance ~1 % of the linear part's at lambda = 1, and as a product of
  /// band-limited fields it has twice their bandwidth, which the tiles (4 texels per shortest
  /// wave) would alias into stripes at the foam's edges.
  double jacobianVariance = 0.0;
};

struct WavePatterns {
  WavePatternParams params;         ///< as used (sizes filled in, reference wind clamped)
  /// Radial band edges, rad/m: pattern i holds the modes with kEdge[i] <= |k| < kEdge[i+1].
  std::array<double, kPatternCount + 1> kEdge{};
  /// h0(k) per [set][pattern]: fftSize² complex amplitudes, row-major (y then x), mode
  /// (mx, my) at index (my mod N) N + (mx mod N), k = 2 pi (mx, my) / size. The surface is
  /// h(x, t) = sum_k h(k, t) e^{i k.x}, h(k, t) = h0(k) e^{-i w t} + conj(h0(-k)) e^{i w t}
  /// (waves travel towards +k).
  std::array<std::array<std::vector<std::complex<float>>, kPatternCount>, kPatternSets> h0;
  std::array<std::array<PatternStats, kPatternCount>, kPatternSets> stats;
  /// Set s's wind direction in its tile's axes, radians counter-clockwise from +x (0, pi/4).
  [[nodiscard]] static double setWindAngleRad(int set);
};

/// Builds the patterns' initial spectra. Deterministic for given params. Throws og::InputError
/// for parameters out of range.
WavePatterns makeWavePatterns(const WavePatternParams& params);

/// Directional elevation spectrum S(k, phi), m⁴ (variance per unit area of wave-vector space):
/// the Elfouhaily omnidirectional spectrum over k times the spreading
/// D = (1 + Delta cos 2phi)(1 + cos phi) / (2 pi): Elfouhaily's up/cross-wind spreading
/// (Eqs. 57-59) with its energy moved to the downwind half-plane (waves run with the wind);
/// phi from the wind direction. Integrates to the height variance.
double directionalSpectrum(double k, double phiRad, double u10);

/// The waves' time as a fraction of their repeat period, [0, 1), for any `timeS` (s, negative
/// too), in double: the phase every mode's integer frequency step multiplies.
[[nodiscard]] double waveRepeatFraction(double timeS);

/// Angular frequency of the patterns: omega(k) rounded to a multiple of 2 pi / kWaveRepeatPeriodS
/// (at least one step); returned as that integer multiple.
std::uint32_t patternFrequencyStep(double k);

/// Per-wind tables for the shaders (shaders/ocean/patterns.glsl) at speeds 0, 1, ... 50 m/s.
struct PatternTableEntry {
  double heightScale = 0.0;  ///< sqrt(height variance at U / at the reference wind)
  double slopeScale = 0.0;   ///< sqrt(slope variance at U / at the reference wind)
  SlopeVariance slope;       ///< the band's slope variance at U in the local wind's frame
  double jacobianVariance = 0.0;  ///< the band's whitecap Jacobian variance at U
};
struct PatternTables {
  static constexpr int kSpeeds = 51;  ///< 0 .. 50 m/s, one per m/s
  std::array<std::array<PatternTableEntry, kPatternCount>, kSpeeds> pattern;
  /// Slope variance of the spectrum outside the patterns' bands (mostly waves < 2 cm).
  std::array<SlopeVariance, kSpeeds> tail;
  /// Variance of the whitecaps' Jacobian j over the whole sea at U (sum over patterns).
  std::array<double, kSpeeds> jacobianVariance;
  /// The whole sea's slope variance at U (bands + tail), in the local wind's frame.
  [[nodiscard]] SlopeVariance totalSlopeVariance(int speed) const;
};
PatternTables makePatternTables(const WavePatterns& patterns);

/// Share of the sea's variance below which a pattern counts as empty (firstPatternWithWaves).
inline constexpr double kEmptyPatternShare = 1e-6;
/// The first pattern (largest first) holding waves at any wind the patterns are used for (up to
/// the reference wind, `tables`' columns 0 .. ceil(reference)): the patterns before it carry less
/// than kEmptyPatternShare of the height and of the slope variance, in the realisation (their
/// textures, as each column scales them) and in the tables' analytic bands. Under light winds
/// the longest tiles are empty (the 4983 m tile holds ~1e-8 of the slopes at 7 m/s), and the
/// shaders' loops skip them (shaders/ocean/patterns.glsl, uPatternFirst). At most
/// kPatternCount - 1.
[[nodiscard]] int firstPatternWithWaves(const WavePatterns& patterns, const PatternTables& tables);

/// Whitecaps (Dupuy 2012 Eq. 6): the fraction of sea whose Jacobian j of the horizontal
/// displacement is below the breaking threshold, for j ~ Normal(mu, sigma²):
/// W = 1/2 erfc((mu - epsilon) / (sqrt 2 sigma)).
/// epsilon is fitted to Monahan & O'Muircheartaigh 1980 between 8 and 20 m/s (within a
/// factor 1.8 there; docs/ocean.md has the table).
inline constexpr double kWhitecapThreshold = 0.80;
double whitecapCoverage(double jacobianMean, double jacobianVariance);

/// Whitecap coverage of the whole sea (mean j = 1) for a 10 m wind of u10 m/s with patterns
/// made for that wind: what `spectrum --json` reports as whitecap_coverage.
double whitecapCoverageForWind(double u10, const WavePatternParams& base = {});

/// Monahan & O'Muircheartaigh (1980): W = 3.84e-6 U^3.41, the measured whitecap fraction.
double monahanWhitecapCoverage(double u10);

}  // namespace og::ocean
