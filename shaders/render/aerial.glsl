// Aerial perspective between the eye and a point of the globe's surface (or the sea), with the
// geometry convention of render/globe.frag: the tables' sphere of radius R = bottomRadius, the
// eye at R + uCamAltitude, the path length t kept exact and its zenith cosine chosen so that
// the path joins the eye's altitude to altitude 0 (see globe.frag's header).
//
// With AERIAL_TABLE the paths to sea level come from this frame's table
// (render/aerial_table.comp, render/AerialTable): for a fixed eye and Sun they
// depend only on the path's length d and nu = cos(view, Sun), so 64 x 256 entries of the
// phase-free scattering (ten lookups into the 4D tables each) serve every pixel with three
// bilinear lookups, the phase functions applied per pixel (Mie's forward peak needs them).
#include "atmosphere/model.glsl"

uniform vec3 uCamUp;        // geodetic normal under the camera, ECEF axes
uniform float uCamAltitude; // camera height above the ellipsoid, m

// The table's size: nu along x (linear in [-1, 1]), the path along y (its share of
// [uCamAltitude, the horizon's distance] as (1 - cos(pi y)) / 2: finer at both ends, near the
// eye and where the paths graze the horizon). Used from 20 km to 500 km up
// (GlobeRenderer::kAerialTableMaxHeightM): farther out the terminator and the limb change
// faster across its entries (errors at single pixels of 4.7 % from 950 km, 26 % from 20 000 km).
const ivec2 AERIAL_TABLE_SIZE = ivec2(64, 256);

// The horizon's distance from the eye on the tables' sphere, m.
float aerialHorizonM() {
  float h = uCamAltitude;
  return sqrt(h * (2.0 * uAtmosphere.bottomRadius + h));
}

// The path's length for the table's row coordinate y in [0, 1], and back.
float aerialTableDistance(float y) {
  float h = max(uCamAltitude, 0.0);
  return h + (0.5 - 0.5 * cos(PI * y)) * (aerialHorizonM() - h);
}
float aerialTableRow(float d) {
  float h = max(uCamAltitude, 0.0);
  return acos(1.0 - 2.0 * clamp((d - h) / max(aerialHorizonM() - h, 1e-3), 0.0, 1.0)) / PI;
}

// The phase-free aerial perspective of a path of length d (≤ the horizon's) to altitude 0:
// transmittance, Rayleigh and Mie in-scatter (atmosphere/functions.glsl's aerialScatteringToPoint).
void aerialScatteringToSeaLevel(float d, float nu, float muS, out vec3 transmittance, out vec3 rayleigh,
                                out vec3 mie) {
  float R = uAtmosphere.bottomRadius;
  float h = uCamAltitude;
  float r = R + h;
  float rho2 = h * (2.0 * R + h);
  float mu = -(rho2 + d * d) / (2.0 * r * max(d, 1e-3));
  aerialScatteringToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie, r, mu, muS, nu, d,
                          transmittance, rayleigh, mie);
}

#ifdef AERIAL_TABLE
layout(binding = OG_UNIT_AERIAL_TABLE) uniform sampler2DArray uAerialTable;  // T.rgb R.r; R.gb M.rg; M.b
#endif

// The light of a path of length d (clamped to the horizon's distance) to sea level along a ray
// at nu = cos(ray, Sun), the Sun at sunDir: transmittance and in-scattered radiance.
void aerialToSeaLevel(float d, float nu, vec3 sunDir, out vec3 transmittance, out vec3 inscatter) {
  d = min(d, aerialHorizonM());
  vec3 rayleigh, mie;
#ifdef AERIAL_TABLE
  vec2 st = (vec2(0.5 * (nu + 1.0), aerialTableRow(d)) * vec2(AERIAL_TABLE_SIZE - 1) + 0.5) / vec2(AERIAL_TABLE_SIZE);
  vec4 a = texture(uAerialTable, vec3(st, 0.0)), b = texture(uAerialTable, vec3(st, 1.0));
  float c = texture(uAerialTable, vec3(st, 2.0)).x;
  transmittance = a.rgb;
  rayleigh = vec3(a.a, b.rg);
  mie = vec3(b.ba, c);
#else
  aerialScatteringToSeaLevel(d, nu, dot(sunDir, uCamUp), transmittance, rayleigh, mie);
#endif
  inscatter = rayleigh * rayleighPhase(nu) + mie * miePhase(uAtmosphere.miePhaseG, nu);
}

// The light of the path from the eye to a point of the surface: dir, unit view ray (ECEF axes);
// t: distance to the point, m; sunDir: unit, towards the Sun. What the point sends towards the
// eye arrives as surface * transmittance + inscatter.
void aerialPerspective(vec3 dir, float t, vec3 sunDir, out vec3 transmittance, out vec3 inscatter) {
  aerialToSeaLevel(t, dot(dir, sunDir), sunDir, transmittance, inscatter);
}

// surface: radiance leaving the point towards the eye; the rest as aerialPerspective.
vec3 withAerialPerspective(vec3 surface, vec3 dir, float t, vec3 sunDir) {
  vec3 transmittance, inscatter;
  aerialPerspective(dir, t, sunDir, transmittance, inscatter);
  return surface * transmittance + inscatter;
}

// The terrain's table (TERRAIN_AERIAL_TABLE in terrain/terrain.vert; render/aerial_table.comp
// with AERIAL_TABLE_TERRAIN, render/AerialTable): for a fixed eye and Sun the path
// to a point at altitude hP depends only on its length d, hP and nu = cos(view, Sun) (its zenith
// cosine follows from d and hP on the tables' sphere, as terrain.vert's exact path takes it).
// Per frame AERIAL_TERRAIN_SIZE entries of the phase-free scattering serve every vertex with
// three trilinear lookups instead of ten into the 4D tables: llvmpipe shades vertices on one
// thread, where these were a sixth of sea-2m-horizon's frame. Axes: nu (x, linear in [-1, 1]);
// d (y: over the distances at which the eye can see a point from 0 to AERIAL_TERRAIN_TOP_M up:
// aerialTerrainDistance); hP (z: over the altitudes the eye can see at that
// distance, as z², fine at the lowest: the points straight below and those at the sea's
// horizon). So every entry is a path the eye can see: an entry of a path shorter than the
// height it spans, or lower than the horizon, would be another path (its zenith cosine
// clamped) and spoil the interpolation next to it (the ground straight down from 300 km came
// out 1 % dark; the far coasts from 2 m mixed paths of 5 and 50 km). In one RGBA32F 3D
// texture of three blocks along x: (T.rgb, R.r), (R.gb, M.rg), (M.b, -, -, -).
const ivec3 AERIAL_TERRAIN_SIZE = ivec3(16, 128, 16);
const float AERIAL_TERRAIN_TOP_M = 9000.0;  // points higher are looked up at this altitude
// Paths beyond the horizon pass at least this far over the tables' sphere (at its last
// kilometre: 0 at the horizon): Bruneton's functions take a ray that grazes it, in float, for
// one that hits the ground.
const float AERIAL_TERRAIN_CLEARANCE_M = 10.0;

// The range of distances of the table, m: from the nearest point (straight below, at the top
// altitude if the eye is above it) to the farthest (at the top altitude over the horizon).
vec2 aerialTerrainDistancesM() {
  float top = AERIAL_TERRAIN_TOP_M;
  return vec2(max(uCamAltitude - top, 0.0), aerialHorizonM() + sqrt(top * (2.0 * uAtmosphere.bottomRadius + top)));
}

// The table's rows: the first AERIAL_TERRAIN_NEAR_ROWS + 1 evenly from the nearest distance to
// the eye's height (the points straight below, whose lowest altitude falls as the distance
// grows: a row at the height itself, where that stops at sea level, keeps the kink off the
// interpolation), the rest as (1 - cos(pi s)) / 2 on to the farthest (fine at both ends).
const int AERIAL_TERRAIN_NEAR_ROWS = 31;
float aerialTerrainDistance(float y) {
  vec2 ds = aerialTerrainDistancesM();
  float near = float(AERIAL_TERRAIN_NEAR_ROWS) / float(AERIAL_TERRAIN_SIZE.y - 1);
  if (y <= near) return mix(ds.x, uCamAltitude, y / near);
  float s = (y - near) / (1.0 - near);
  return uCamAltitude + (0.5 - 0.5 * cos(PI * s)) * (ds.y - uCamAltitude);
}
float aerialTerrainRowOf(float d) {
  vec2 ds = aerialTerrainDistancesM();
  float near = float(AERIAL_TERRAIN_NEAR_ROWS) / float(AERIAL_TERRAIN_SIZE.y - 1);
  if (d <= uCamAltitude) return near * clamp((d - ds.x) / max(uCamAltitude - ds.x, 1e-3), 0.0, 1.0);
  float s = acos(1.0 - 2.0 * clamp((d - uCamAltitude) / (ds.y - uCamAltitude), 0.0, 1.0)) / PI;
  return near + s * (1.0 - near);
}

// The range of altitudes the eye can see at distance d, m: over the sea's horizon beyond it (and
// straight below within the eye's height), up to the top altitude (or straight above).
vec2 aerialTerrainAltitudesM(float d) {
  float R = uAtmosphere.bottomRadius;
  float beyond = max(d - aerialHorizonM(), 0.0);
  float overHorizon = beyond * beyond / (sqrt(R * R + beyond * beyond) + R);  // sqrt(R² + b²) - R
  float lowest = max(uCamAltitude - d, overHorizon + AERIAL_TERRAIN_CLEARANCE_M * min(beyond / 1000.0, 1.0));
  float highest = min(uCamAltitude + d, AERIAL_TERRAIN_TOP_M);
  return vec2(min(lowest, highest), highest);
}

// The phase-free aerial perspective of a path of length d to a point at altitude hP ≥ 0.
void aerialScatteringToAltitude(float d, float hP, float nu, float muS, out vec3 transmittance, out vec3 rayleigh,
                                out vec3 mie) {
  float R = uAtmosphere.bottomRadius;
  float r = R + uCamAltitude;
  float rP = R + hP;
  d = max(d, 1e-3);
  float mu = clamp(((hP - uCamAltitude) * (rP + r) - d * d) / (2.0 * r * d), -1.0, 1.0);  // rP² - r² without cancelling
  aerialScatteringToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie, r, mu, muS, nu, d,
                          transmittance, rayleigh, mie);
}

// The table's entry (y, z) in [0, 1]²: its path's length and end altitude, m.
vec2 aerialTerrainPath(vec2 yz) {
  float d = aerialTerrainDistance(yz.x);
  vec2 hs = aerialTerrainAltitudesM(d);
  return vec2(d, hs.x + (hs.y - hs.x) * yz.y * yz.y);
}

#ifdef TERRAIN_AERIAL_TABLE
layout(binding = OG_UNIT_TERRAIN_AERIAL_TABLE) uniform sampler3D uTerrainAerialTable;

// The light of the path from the eye to a point at altitude hP at distance d along a ray at
// nu = cos(ray, Sun): transmittance and in-scattered radiance, from this frame's table. Beyond
// its ranges d and hP are clamped (a point higher than AERIAL_TERRAIN_TOP_M, or where the eye
// cannot see it; at or under sea level d to the horizon's, as terrain.vert's exact path and
// aerialToSeaLevel take it).
void aerialToAltitudeFromTable(float d, float hP, float nu, out vec3 transmittance, out vec3 inscatter) {
  vec3 size = vec3(AERIAL_TERRAIN_SIZE);
  vec2 ds = aerialTerrainDistancesM();
  d = clamp(d, ds.x, hP <= 0.0 ? max(aerialHorizonM(), ds.x) : ds.y);
  float y = aerialTerrainRowOf(d);
  vec2 hs = aerialTerrainAltitudesM(d);
  float z = sqrt(clamp((hP - hs.x) / max(hs.y - hs.x, 1e-3), 0.0, 1.0));
  // Texel centres of the first block; the others lie size.x texels along (never filtered into).
  vec3 p = (vec3(0.5 * clamp(nu, -1.0, 1.0) + 0.5, y, z) * (size - 1.0) + 0.5) / vec3(3.0 * size.x, size.yz);
  float block = 1.0 / 3.0;
  vec4 a = texture(uTerrainAerialTable, p), b = texture(uTerrainAerialTable, p + vec3(block, 0.0, 0.0));
  float c = texture(uTerrainAerialTable, p + vec3(2.0 * block, 0.0, 0.0)).x;
  transmittance = a.rgb;
  inscatter = vec3(a.a, b.rg) * rayleighPhase(nu) + vec3(b.ba, c) * miePhase(uAtmosphere.miePhaseG, nu);
}
#endif
