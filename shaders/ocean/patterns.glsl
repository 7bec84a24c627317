// The sea from the FFT wave patterns (render/OceanPatterns, Dupuy & Bruneton 2012) filtered by
// the footprint as Bruneton et al. 2010 filter their waves: what the footprint resolves is
// geometry (the vertex displacement) or the mean normal (the mean slope of the footprint, from
// the mip-mapped slope texture), and the slope variance inside the footprint (the mip-mapped
// second moment minus the squared mean: LEAN mapping, Olano & Baker 2010, split along/across the
// wind as the band's spectrum splits it) plus the spectrum's tail below the finest pattern goes
// into the BRDF. Whitecaps: the Jacobian's mean in the footprint from the mip-mapped j, its
// variance lambda² times the slopes' (same power spectrum; Dupuy 2012 Eqs. 6-8). One texture
// lookup per pattern and direction bin.
//
// Local wind, place by place: the patterns exist for 8 wind directions 45° apart (two spectra,
// each turned by quarter turns, which are exact on the periodic tiles); a point blends the two
// bins around its wind with weights cos/sin(pi/2 f) (variance preserving), and scales each
// band to its wind speed with the per-wind table. No lookup is ever turned by an angle that
// varies in space, so waves keep their shape however far from the frame's origin.
//
// Coordinates: `xy` is the point in the ocean frame's tangent plane (x east, y north, m); the
// wave field is turned by uFieldRotation relative to the frame and shifted by its offset
// (folded modulo each tile on the CPU, in double: ocean/OceanFrame). Patterns are ordered
// largest first, so loops over them stop at the first one the footprint averages out.
// Needs PATTERN_COUNT defined (render/OceanPatterns::shaderDefines).
#include "common/constants.glsl"

layout(binding = OG_UNIT_PATTERN_DISPLACEMENT) uniform sampler2DArray uPatternDisplacement; // (lambda Dx, lambda Dy, h, 0)
layout(binding = OG_UNIT_PATTERN_SLOPES) uniform sampler2DArray uPatternSlopes;       // (s_u, s_c, s_u² + s_c², j)
uniform float uPatternSizeM[PATTERN_COUNT];
uniform vec2 uPatternOffsetM[PATTERN_COUNT];  // field offset modulo each tile, field axes
uniform vec2 uFieldRotation;                  // (cos, sin): field axes -> frame axes
uniform float uPatternChoppiness[PATTERN_COUNT];  // lambda_i; > 0: in the whitecaps' Jacobian
uniform float uPatternAmplitude;              // 0..1: fades the resolved waves out (12-20 km)
uniform float uWhitecapThreshold;             // epsilon of Dupuy 2012 Eq. 3
uniform float uPatternFftSize;                 // texels per tile side
uniform float uPatternTopLod;                 // log2(uPatternFftSize): the 1x1 mip level
// The first pattern with waves (ocean::firstPatternWithWaves): under light winds the longest
// tiles are empty (less than 1e-6 of the sea's heights and slopes), and every loop starts here.
uniform int uPatternFirst;

// The per-wind tables (render/OceanPatterns, a uniform block: llvmpipe reads it faster than a
// texture): column c = wind speed c m/s (0..50); row i < PATTERN_COUNT: pattern i's
// (height scale, slope scale, up and cross slope variance of its band at that wind); row
// PATTERN_COUNT: (tail up, tail cross, Jacobian variance of the whole sea, -); row
// PATTERN_COUNT + 1 + i: (pattern i's Jacobian variance at that wind, -, -, -).
const int PATTERN_TABLE_COLUMNS = 51;
layout(std140, binding = OG_BLOCK_PATTERN_TABLE) uniform PatternTable {
  vec4 uPatternTable[PATTERN_TABLE_COLUMNS * (2 * PATTERN_COUNT + 1)];  // row by row
};
vec4 patternTable(int row, float speedMs) {
  float c = clamp(speedMs, 0.0, 50.0);
  int c0 = min(int(c), PATTERN_TABLE_COLUMNS - 2);
  int at = row * PATTERN_TABLE_COLUMNS + c0;
  return mix(uPatternTable[at], uPatternTable[at + 1], c - float(c0));
}

// The two direction bins around a wind blowing towards `thetaField` (radians, counter-clockwise
// from the field's x axis), and their weights (w0² + w1² = 1).
// With each bin's turn from the field's axes (binTurn: cos, sin of bin x 45°) and from the
// wind's (windTurn: of bin x 45° - thetaField), the same for every pattern: taken once, not per
// pattern and bin (a GPU's compiler may hoist them out of the pattern loop; llvmpipe's did not).
struct WindBins {
  int bin[2];
  float weight[2];
  vec2 binTurn[2];
  vec2 windTurn[2];
};
// PATTERN_ONE_BIN where every point's wind lies along one bin (a constant wind along one of
// them: render/OceanRenderer::windAlongOneBin): the other bin's weight is under 1e-3 (its
// share of the variance under 1e-6) and the loops over the bins take one trip (a compiled
// constant: llvmpipe runs a loop's first trip even where a uniform leaves none).
#ifdef PATTERN_ONE_BIN
const int PATTERN_BINS = 1;
#else
const int PATTERN_BINS = 2;
#endif
WindBins windBins(float thetaField) {
  float b = thetaField / (0.25 * PI);
  b -= 8.0 * floor(b / 8.0);
  WindBins w;
#ifdef PATTERN_ONE_BIN
  // The nearest bin alone (a wind along bin 0 can round to just below it), weight 1 (the other
  // bin's is under 1e-3); the second slot the same bin, weight 0.
  w.bin[0] = w.bin[1] = int(floor(b + 0.5)) & 7;
  w.weight[0] = 1.0;
  w.weight[1] = 0.0;
#else
  int b0 = int(floor(b)) & 7;
  float f = b - floor(b);
  w.bin[0] = b0;
  w.bin[1] = (b0 + 1) & 7;
  w.weight[0] = cos(0.5 * PI * f);
  w.weight[1] = sin(0.5 * PI * f);
#endif
  for (int k = 0; k < PATTERN_BINS; ++k) {
    float binAngle = float(w.bin[k]) * 0.25 * PI;
    w.binTurn[k] = vec2(cos(binAngle), sin(binAngle));
    w.windTurn[k] = vec2(cos(binAngle - thetaField), sin(binAngle - thetaField));
  }
#ifdef PATTERN_ONE_BIN
  w.binTurn[1] = w.binTurn[0];  // (the unused slot defined)
  w.windTurn[1] = w.windTurn[0];
#endif
  return w;
}

// The wind's direction in the field's axes from its azimuth (radians clockwise from north).
float fieldWindAngle(float azimuth) {
  float frameAngle = 0.5 * PI - azimuth;
  return frameAngle - atan2Safe(uFieldRotation.y, uFieldRotation.x);
}

#ifdef PATTERN_CONSTANT_WIND
// The constant wind's bin, as windBins(fieldWindAngle(azimuth)) finds it, and the field angle's
// (cos, sin): computed once by the CPU (OceanPatterns::setConstantWind), not per point.
uniform int uWindBinConst;
uniform vec4 uWindBinTurnsConst;  // (binTurn, windTurn) of that bin
uniform vec2 uWindFieldTurnConst;  // (cos, sin) of fieldWindAngle
#endif

// The bins around a wind blowing towards `azimuth` (radians clockwise from north), and the
// turn (cos, sin) from the field's axes to the wind's.
WindBins windBinsOf(float azimuth, out vec2 fieldTurn) {
#ifdef PATTERN_CONSTANT_WIND
  WindBins w;
  w.bin[0] = w.bin[1] = uWindBinConst;
  w.weight[0] = 1.0;
  w.weight[1] = 0.0;
  w.binTurn[0] = w.binTurn[1] = uWindBinTurnsConst.xy;
  w.windTurn[0] = w.windTurn[1] = uWindBinTurnsConst.zw;
  fieldTurn = uWindFieldTurnConst;
  return w;
#else
  float thetaField = fieldWindAngle(azimuth);
  fieldTurn = vec2(cos(thetaField), sin(thetaField));
  return windBins(thetaField);
#endif
}

// v turned counter-clockwise by the angle whose (cos, sin) is cs.
vec2 turn2(vec2 v, vec2 cs) { return vec2(cs.x * v.x - cs.y * v.y, cs.y * v.x + cs.x * v.y); }
// Quarter turns, exact: q in 0..3, counter-clockwise.
vec2 quarterTurn(vec2 v, int q) {
  return q == 0 ? v : q == 1 ? vec2(-v.y, v.x) : q == 2 ? -v : vec2(v.y, -v.x);
}

// Texture coordinates of field point p in bin `bin`'s copy of pattern i.
vec3 patternCoord(vec2 p, int bin, int i) {
  vec2 local = quarterTurn(p + uPatternOffsetM[i], (4 - (bin >> 1)) & 3);
  return vec3(local / uPatternSizeM[i], float((bin & 1) * PATTERN_COUNT + i));
}

// Level of detail at which pattern i's texels match a footprint (m). Validation variants
// (`oceanglobe validate`, docs/validation.md): OCEAN_VALIDATION_REFERENCE resolves every
// pattern fully whatever the footprint (the brute-force reference supersamples instead);
// OCEAN_VALIDATION_BRDF_ONLY resolves none (a flat sea, the whole slope variance in the BRDF).
float patternLod(float footprintM, int i) {
#if defined(OCEAN_VALIDATION_REFERENCE)
  return 0.0;
#elif defined(OCEAN_VALIDATION_BRDF_ONLY)
  return uPatternTopLod;
#else
  return log2(max(footprintM, 1e-6) * uPatternFftSize / uPatternSizeM[i]);
#endif
}
// Whether a footprint (m) resolves pattern i: patternLod(footprintM, i) < uPatternTopLod, the
// 1 x 1 level log2(uPatternFftSize), without the logarithm: the footprint is under the tile.
bool patternResolved(float footprintM, int i) {
#if defined(OCEAN_VALIDATION_REFERENCE) || defined(OCEAN_VALIDATION_BRDF_ONLY)
  return patternLod(footprintM, i) < uPatternTopLod;
#else
  return footprintM < uPatternSizeM[i];
#endif
}

vec2 fieldPosition(vec2 xy) { return vec2(dot(xy, uFieldRotation), dot(xy, vec2(-uFieldRotation.y, uFieldRotation.x))); }
vec2 frameVector(vec2 v) { return vec2(dot(v, vec2(uFieldRotation.x, -uFieldRotation.y)), dot(v, uFieldRotation.yx)); }

// Displacement of the sea surface at xy (Dupuy 2012 Eq. 1), filtered by the grid's cell size
// (Bruneton 2010 Eq. 2: waves shorter than ~2 cells are averaged out by the mip level);
// `wind` = (speed m/s, azimuth rad). Frame axes, m.
vec3 oceanDisplacement(vec2 xy, float cellFootprintM, vec2 wind) {
  vec2 p = fieldPosition(xy);
  vec2 fieldTurn;
  WindBins wb = windBinsOf(wind.y, fieldTurn);
  vec3 d = vec3(0.0);
  for (int i = uPatternFirst; i < PATTERN_COUNT; ++i) {
    float lod = patternLod(0.5 * cellFootprintM, i);
    if (lod >= uPatternTopLod) break;
    float scale = patternTable(i, wind.x).x;
    for (int k = 0; k < PATTERN_BINS; ++k) {
      if (wb.weight[k] < 1e-3) continue;
      vec3 t = textureLod(uPatternDisplacement, patternCoord(p, wb.bin[k], i), lod).xyz;
      d += (wb.weight[k] * scale) * vec3(quarterTurn(t.xy, wb.bin[k] >> 1), t.z);
    }
  }
  return vec3(frameVector(d.xy), d.z) * uPatternAmplitude;
}

// A 2x2 covariance (xx, yy, xy) turned counter-clockwise by the angle whose (cos, sin) is turn.
vec3 rotateCovariance(vec3 c, vec2 turn) {
  float cs = turn.x, sn = turn.y;
  float xx = cs * cs * c.x + sn * sn * c.y - 2.0 * cs * sn * c.z;
  float yy = sn * sn * c.x + cs * cs * c.y + 2.0 * cs * sn * c.z;
  float xy = cs * sn * (c.x - c.y) + (cs * cs - sn * sn) * c.z;
  return vec3(xx, yy, xy);
}

// What a pixel of footprint `footprintM` (m) sees of the sea at xy under wind (speed, azimuth).
struct SeaSurface {
  vec2 meanSlope;   // dz/dx, dz/dy of the footprint's mean surface, frame axes
  vec2 variance;    // unresolved slope variance along/across the local wind (BRDF)
  vec3 covariance;  // the same with its cross term: (xx, yy, xy) in the local wind's frame
  vec2 jacobian;    // mean and variance of the whitecaps' Jacobian in the footprint
};

// Sums of resolved patterns' statistics in a footprint: the mean slope (field axes), the slope
// covariance left in the footprint (xx, yy, xy in the local wind's frame) and the whitecaps'
// Jacobian (mean and variance, the constant 1 of the mean not included).
struct PatternSums {
  vec2 mean;
  vec3 cov;
  vec2 jac;
  float share[PATTERN_COUNT];  // of each pattern (patternVertexShare), the rest the pixel's
};

// Where the patterns are looked up (docs/performance.md, "The ocean pass"): a pattern whose
// texels span two grid cells or more is smooth across a cell, so the grid's vertices look it up
// (at the pixel footprint's level of detail, which there is below 0: magnified texels) and the
// triangles interpolate it; per pixel only the patterns whose texels are near the footprint
// remain. Share of pattern i taken per vertex at the pixel level of detail `lod`: 1 where a texel
// spans 2 cells or more, 0 where it spans 1 cell or less, linear between, so the vertices' and
// the pixels' shares of every pattern add up to 1 (Bruneton 2010's split of the spectrum between
// geometry, normals and BRDF is untouched: only where the normals' lookups run moves).
// uPatternVertexLod: -log2(cell size in pixels), set by render/OceanRenderer; patternVertexShare
// is 0 everywhere with it at or above uPatternTopLod (everything per pixel).
uniform float uPatternVertexLod;
float patternVertexShare(float lod) { return clamp(uPatternVertexLod - lod, 0.0, 1.0); }

// Adds pattern i's statistics at level of detail `lod` in the footprint around field point p,
// times `share` (the part of the pattern this caller stands for), to `sums`: the mean slope of
// the footprint and its slope variance (the mip-mapped second moment minus the squared mean,
// LEAN mapping) of the two wind bins, and the Jacobian's mean and variance (lambda² times the
// slopes', Dupuy 2012 Eqs. 6-8). `band`: patternBand(i, wind speed).
void addPatternStatistics(INOUT(PatternSums) sums, vec2 p, WindBins wb, int i, float lod,
                          vec2 band, float share) {
  float s = band.x;
  float alongShare = band.y;
  float lambda2 = uPatternChoppiness[i] * uPatternChoppiness[i];
  for (int k = 0; k < PATTERN_BINS; ++k) {
    float w = wb.weight[k];
    vec4 m = textureLod(uPatternSlopes, patternCoord(p, wb.bin[k], i), lod);
    sums.mean += (share * w * s) * turn2(m.xy, wb.binTurn[k]);
    float variance = share * s * s * max(m.z - dot(m.xy, m.xy), 0.0);
    sums.cov += w * w * rotateCovariance(variance * vec3(alongShare, 1.0 - alongShare, 0.0), wb.windTurn[k]);
    sums.jac += vec2(share * w * s * m.w, w * w * lambda2 * variance);
  }
}

// Pattern i's (slope scale, share of its band's slope variance along the wind) at a wind speed
// (m/s). The footprint's slope variance splits along/across its bin's wind as the band's does
// (the cross moment is not stored: ~m_u m_c where the footprint holds one slope, ~0 where it
// averages many, so the covariance is diagonal either way).
vec2 patternBand(int i, float speedMs) {
  vec4 band = patternTable(i, speedMs);
  return vec2(band.y, band.z / max(band.z + band.w, 1e-12));
}

// The per-wind table values a pixel needs (patternBand per pattern; the averaged-out statistics
// from pattern i on, i = 0..PATTERN_COUNT: up and cross slope variance with the tail below the
// finest pattern, and the Jacobian's variance), looked up by the grid's vertices: the wind
// varies over kilometres, and the tables' texel fetches cost the pixels as much as a pattern.
struct PatternBands {
  vec2 band[PATTERN_COUNT];
  vec3 averagedFrom[PATTERN_COUNT + 1];
};
PatternBands patternBands(float speedMs) {
  PatternBands b;
  vec3 sum = vec3(patternTable(PATTERN_COUNT, speedMs).xy, 0.0);  // the tail
  b.averagedFrom[PATTERN_COUNT] = sum;
  for (int i = PATTERN_COUNT - 1; i >= 0; --i) {
    b.band[i] = patternBand(i, speedMs);
    sum += vec3(patternTable(i, speedMs).zw, patternTable(PATTERN_COUNT + 1 + i, speedMs).x);
    b.averagedFrom[i] = sum;
  }
  return b;
}

// PatternBands.averagedFrom[first] alone: the averaged-out statistics from pattern `first` on
// at a wind (m/s), for a pixel that looks the tables up itself (PATTERN_BANDS_PER_PIXEL).
vec3 patternAveragedFrom(int first, float speedMs) {
  vec3 sum = vec3(patternTable(PATTERN_COUNT, speedMs).xy, 0.0);
  for (int i = PATTERN_COUNT - 1; i >= first; --i)
    sum += vec3(patternTable(i, speedMs).zw, patternTable(PATTERN_COUNT + 1 + i, speedMs).x);
  return sum;
}

// Where oceanSurface finds the per-wind table values: with PATTERN_CONSTANT_WIND (one wind
// over the whole sea: render/OceanRenderer) the CPU's, the same for every point
// (OceanPatterns::setConstantWind); else the vertices' (`bands`), or with
// PATTERN_BANDS_PER_PIXEL (the deferred sea, which has no vertices) the tables themselves,
// only the entries the pixel's footprint needs.
#if defined(PATTERN_CONSTANT_WIND)
uniform vec2 uPatternBandConst[PATTERN_COUNT];               // patternBands(speed).band
uniform vec3 uPatternAveragedFromConst[PATTERN_COUNT + 1];  // patternBands(speed).averagedFrom
#define PATTERN_BAND(bands, i, speedMs) uPatternBandConst[i]
#define PATTERN_AVERAGED_FROM(bands, first, speedMs) uPatternAveragedFromConst[first]
#elif defined(PATTERN_BANDS_PER_PIXEL)
#define PATTERN_BAND(bands, i, speedMs) patternBand(i, speedMs)
#define PATTERN_AVERAGED_FROM(bands, first, speedMs) patternAveragedFrom(first, speedMs)
#else
#define PATTERN_BAND(bands, i, speedMs) bands.band[i]
#define PATTERN_AVERAGED_FROM(bands, first, speedMs) bands.averagedFrom[first]
#endif

// The vertices' part of the resolved patterns (patternVertexShare) at xy for pixels of
// footprint `pixelFootprintM` (m) there, for the grid's vertex shader to interpolate.
PatternSums oceanVertexPatterns(vec2 xy, float pixelFootprintM, vec2 wind) {
  vec2 p = fieldPosition(xy);
  vec2 fieldTurn;
  WindBins wb = windBinsOf(wind.y, fieldTurn);
  PatternSums sums;
  sums.mean = vec2(0.0);
  sums.cov = vec3(0.0);
  sums.jac = vec2(0.0);
  for (int i = 0; i < PATTERN_COUNT; ++i) sums.share[i] = patternVertexShare(patternLod(pixelFootprintM, i));
  for (int i = uPatternFirst; i < PATTERN_COUNT; ++i) {
    if (sums.share[i] <= 0.0) break;  // finer patterns have larger lods: none of theirs either
    addPatternStatistics(sums, p, wb, i, patternLod(pixelFootprintM, i), patternBand(i, wind.x), sums.share[i]);
  }
  return sums;
}

// The pixel's sea: `vertexSums` is the interpolated oceanVertexPatterns of the grid (zero sums
// and shares: everything per pixel), `bands` the interpolated patternBands(wind speed). The
// pixel takes the part of each pattern that the vertices' interpolated share leaves, so the two
// parts add up to 1 however the footprints of pixel and vertex differ.
SeaSurface oceanSurface(vec2 xy, float footprintM, vec2 wind, PatternSums vertexSums, PatternBands bands) {
  vec2 p = fieldPosition(xy);
  vec2 fieldTurn;  // (cos, sin) of the wind's angle in the field's axes
  WindBins wb = windBinsOf(wind.y, fieldTurn);
  PatternSums sums = vertexSums;
  // The footprint resolves a prefix of the patterns (largest first; lod grows along the list);
  // the rest it averages out entirely. Of the prefix the vertices took the first patterns from
  // uPatternFirst on wholly (a share of 0.999 or more: a prefix too, the shares fall along the
  // list), the next ones in part. Both prefixes counted in loops of constant trips, which the
  // compiler unrolls (as while loops, a logarithm a trip, they cost llvmpipe ~5 ms of
  // sea-8km's ocean pass and ~4 ms of sea-4m's open sea, one thread at 1280x720:
  // docs/performance.md, twenty-fifth session); the lookups in a loop rather than an if in one
  // (llvmpipe runs both sides of an if, but no loop trip after the first that no pixel of a
  // block needs; the first it runs, masked, even where none enters).
  int resolved = 0, taken = uPatternFirst;
  for (int i = 0; i < PATTERN_COUNT; ++i) {
    resolved += patternResolved(footprintM, i) ? 1 : 0;
    taken += i >= uPatternFirst && vertexSums.share[i] >= 0.999 ? 1 : 0;
  }
  int first = min(taken, max(resolved, uPatternFirst));
  for (int i = first; i < resolved; ++i) {
    float lod = patternLod(footprintM, i);
    addPatternStatistics(sums, p, wb, i, lod, PATTERN_BAND(bands, i, wind.x), 1.0 - vertexSums.share[i]);
  }
  // The patterns averaged out entirely and the tail below the finest: their statistics at this
  // wind, analytic.
  vec3 averaged = PATTERN_AVERAGED_FROM(bands, resolved, wind.x);
  vec3 cov = sums.cov + vec3(averaged.xy, 0.0);
  // Faded-out waves (12-20 km): what the mean normal no longer shows goes into the BRDF.
  float a = uPatternAmplitude;
  vec2 meanWind = turn2(sums.mean, vec2(fieldTurn.x, -fieldTurn.y));
  cov += (1.0 - a * a) * vec3(meanWind * meanWind, meanWind.x * meanWind.y);
  SeaSurface r;
  r.meanSlope = frameVector(a * sums.mean);
  r.variance = max(cov.xy, vec2(0.0));
  r.covariance = vec3(r.variance, cov.z);
  r.jacobian = vec2(1.0, averaged.z) + sums.jac;
  return r;
}

// The whole sea's statistics at a wind (what a footprint covering everything sees). With
// PATTERN_CONSTANT_WIND the constant wind's, as the CPU computed them from the same tables
// (OceanPatterns::setConstantWind), whatever is passed.
#ifdef PATTERN_CONSTANT_WIND
uniform vec3 uSeaTotalsConst;  // (slope variance up, cross, the Jacobian's variance)
vec2 seaSlopeVarianceTotal(float speedMs) { return uSeaTotalsConst.xy; }
float seaJacobianVarianceTotal(float speedMs) { return uSeaTotalsConst.z; }
#else
vec2 seaSlopeVarianceTotal(float speedMs) {
  vec2 v = patternTable(PATTERN_COUNT, speedMs).xy;
  for (int i = 0; i < PATTERN_COUNT; ++i) v += patternTable(i, speedMs).zw;
  return v;
}
float seaJacobianVarianceTotal(float speedMs) { return patternTable(PATTERN_COUNT, speedMs).z; }
#endif

// Whitecap coverage of a footprint whose Jacobian is Normal(mean, variance): Dupuy 2012 Eq. 6,
// W = 1/2 erfc((mu - epsilon) / (sqrt(2) sigma)).
float whitecapCoverage(vec2 jacobian) {
  float sigma = sqrt(max(jacobian.y, 1e-10));
  float x = (jacobian.x - uWhitecapThreshold) / (sqrt(2.0) * sigma);
  // erfc(x) for x >= 0 by the same rational approximation as the BRDF's masking (brdf.glsl).
  float e = 2.0 * exp(-x * x) / (2.319 * abs(x) + sqrt(4.0 + 1.52 * x * x));
  return x >= 0.0 ? 0.5 * e : 1.0 - 0.5 * e;
}
