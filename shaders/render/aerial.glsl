// Aerial perspective between the eye and a point of the globe's surface (or the sea), with the
// geometry convention of render/globe.frag: the tables' sphere of radius R = bottomRadius, the
// eye at R + uCamAltitude, the path length t kept exact and its zenith cosine chosen so that
// the path joins the eye's altitude to altitude 0 (see globe.frag's header).
//
// With AERIAL_TABLE the paths to sea level come from this frame's table
// (render/aerial_table.comp, GlobeRenderer::drawAerialTable): for a fixed eye and Sun they
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
