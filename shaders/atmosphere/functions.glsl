// Precomputed atmospheric scattering after Bruneton & Neyret 2008, "Precomputed Atmospheric
// Scattering" (EGSR 2008): the physics shared by the GPU passes and by the double-precision CPU
// reference. src/atmosphere/Reference.cpp compiles this very file as C++ with GLM types, so it is
// written in the common subset of GLSL 4.50 and C++20:
//   * types Real, vec2, vec3, vec4 (float/vec on the GPU, double/dvec on the CPU);
//   * parameters qualified IN(T) / OUT(T) / INOUT(T); no swizzles (rgbOf() instead); explicit Real(...)
//     conversions; no float suffixes; no include directives (the includer provides Real, PI, IN, OUT, INOUT,
//     Texture2D, Texture3D and texture()).
// Units: lengths in metres; directions as cosines of angles (mu: view zenith, muS: Sun zenith,
// nu: view-Sun); radiance and irradiance relative to the solar irradiance at the top of the
// atmosphere (solarIrradiance = 1 is the renderer's unit: a white Lambertian plate facing the
// unattenuated Sun has radiance 1/pi).
//
// Equation numbers: Bruneton & Neyret 2008, Section 2 (physical model and rendering equation)
// and Section 4 (precomputation). The table parameterisation of r and mu by distances to the
// atmosphere boundaries follows the improved mapping of the authors' 2017 revision; the mu_s
// mapping is the paper's exponential one with a configurable lower bound.

// All the model's constants, passed as a uniform struct on the GPU.
struct AtmosphereParameters {
  vec3 solarIrradiance;     // top-of-atmosphere solar irradiance per channel (1 = unit)
  Real sunAngularRadius;    // radians
  Real bottomRadius;        // m, radius of the ground sphere of the tables
  Real topRadius;           // m, radius of the top of the atmosphere
  vec3 rayleighScattering;  // 1/m at altitude 0 (Eq. 1)
  Real rayleighScaleHeight; // m
  vec3 mieScattering;       // 1/m at altitude 0 (Eq. 3)
  vec3 mieExtinction;       // 1/m at altitude 0, scattering + absorption
  Real mieScaleHeight;      // m
  Real miePhaseG;           // Cornette-Shanks asymmetry, (-1, 1)
  vec3 ozoneAbsorption;     // 1/m at the ozone peak
  Real ozoneCenterAltitude; // m
  Real ozoneHalfWidth;      // m, the tent profile reaches 0 this far from the peak
  vec3 groundAlbedo;        // Lambertian ground of the tables, [0, 1]
  Real muSMin;              // lowest Sun zenith cosine stored in the scattering tables
  int transmittanceWidth;   // texels along mu
  int transmittanceHeight;  // texels along r
  int irradianceWidth;      // texels along mu_s
  int irradianceHeight;     // texels along r
  int scatteringR;          // 4D table: r
  int scatteringMu;         // 4D table: mu (even; half below, half above the horizon)
  int scatteringMuS;        // 4D table: mu_s
  int scatteringNu;         // 4D table: nu (packed with mu_s along x of the 3D texture)
  int sphereSamples;        // zenith steps of the direction integrals (azimuth: twice as many)
};

const int TRANSMITTANCE_STEPS = 500;
const int SCATTERING_STEPS = 50;

vec3 rgbOf(vec4 v) { return vec3(v.x, v.y, v.z); }
Real clampCosine(Real mu) { return clamp(mu, Real(-1.0), Real(1.0)); }
Real safeSqrt(Real a) { return sqrt(max(a, Real(0.0))); }
Real clampRadius(IN(AtmosphereParameters) atm, Real r) {
  return clamp(r, atm.bottomRadius, atm.topRadius);
}

// ---------------------------------------------------------------------------------------------
// Geometry of a ray from radius r with view zenith cosine mu in the spherical shell.

// r^2 - bottom^2 factored so it stays accurate a few metres above the ground in float.
Real horizonDistanceSq(IN(AtmosphereParameters) atm, Real r) {
  return (r - atm.bottomRadius) * (r + atm.bottomRadius);
}
// Distance from the ground to the top boundary along a tangent ray, m.
Real topHorizonDistance(IN(AtmosphereParameters) atm) {
  return safeSqrt((atm.topRadius - atm.bottomRadius) * (atm.topRadius + atm.bottomRadius));
}
// Distance to the top boundary (|p + d v| = topRadius, far root), m.
Real distanceToTop(IN(AtmosphereParameters) atm, Real r, Real mu) {
  Real disc = (atm.topRadius - r) * (atm.topRadius + r) + r * r * mu * mu;
  return max(-r * mu + safeSqrt(disc), Real(0.0));
}
// Distance to the ground (near root), m; meaningful when rayHitsGround().
Real distanceToBottom(IN(AtmosphereParameters) atm, Real r, Real mu) {
  Real disc = r * r * mu * mu - horizonDistanceSq(atm, r);
  return max(-r * mu - safeSqrt(disc), Real(0.0));
}
bool rayHitsGround(IN(AtmosphereParameters) atm, Real r, Real mu) {
  return mu < 0.0 && r * r * mu * mu >= horizonDistanceSq(atm, r);
}
Real distanceToBoundary(IN(AtmosphereParameters) atm, Real r, Real mu, bool hitsGround) {
  return hitsGround ? distanceToBottom(atm, r, mu) : distanceToTop(atm, r, mu);
}
// Radius and zenith cosine at distance d along the ray.
Real radiusAlong(IN(AtmosphereParameters) atm, Real r, Real mu, Real d) {
  return clampRadius(atm, sqrt(d * d + 2.0 * r * mu * d + r * r));
}

// ---------------------------------------------------------------------------------------------
// Density profiles and extinction: Eq. 1 (Rayleigh) and Eq. 3 (Mie), both exponential in the
// altitude h; ozone (not in the 2008 paper) absorbs only, with a tent profile.

Real rayleighDensity(IN(AtmosphereParameters) atm, Real h) {
  return clamp(exp(-h / atm.rayleighScaleHeight), Real(0.0), Real(1.0));
}
Real mieDensity(IN(AtmosphereParameters) atm, Real h) {
  return clamp(exp(-h / atm.mieScaleHeight), Real(0.0), Real(1.0));
}
Real ozoneDensity(IN(AtmosphereParameters) atm, Real h) {
  return max(1.0 - abs(h - atm.ozoneCenterAltitude) / atm.ozoneHalfWidth, Real(0.0));
}
// beta_e(h) = beta_R^s(h) + beta_M^e(h) + beta_O^a(h), 1/m.
vec3 extinctionAt(IN(AtmosphereParameters) atm, Real h) {
  return atm.rayleighScattering * rayleighDensity(atm, h) +
         atm.mieExtinction * mieDensity(atm, h) + atm.ozoneAbsorption * ozoneDensity(atm, h);
}

// Phase functions: Rayleigh (Eq. 2) and Cornette-Shanks for Mie (Eq. 4), 1/sr.
Real rayleighPhase(Real nu) { return 3.0 / (16.0 * PI) * (1.0 + nu * nu); }
Real miePhase(Real g, Real nu) {
  Real k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / pow(max(1.0 + g * g - 2.0 * g * nu, Real(1e-6)), Real(1.5));
}

// ---------------------------------------------------------------------------------------------
// Transmittance, Eq. 5: T(x, y) = exp(-integral of beta_e over [x, y]), to the top boundary,
// by the trapezoidal rule.

vec3 computeTransmittanceToTop(IN(AtmosphereParameters) atm, Real r, Real mu) {
  Real dx = distanceToTop(atm, r, mu) / Real(TRANSMITTANCE_STEPS);
  vec3 depth = vec3(0.0);
  for (int i = 0; i <= TRANSMITTANCE_STEPS; ++i) {
    Real di = Real(i) * dx;
    Real hi = sqrt(di * di + 2.0 * r * mu * di + r * r) - atm.bottomRadius;
    Real w = (i == 0 || i == TRANSMITTANCE_STEPS) ? 0.5 : 1.0;
    depth += extinctionAt(atm, hi) * (w * dx);
  }
  return exp(-depth);
}

// Texture coordinates in [0.5/n, 1 - 0.5/n] so texel centres hold the end points.
Real unitToTexCoord(Real x, int n) { return 0.5 / Real(n) + x * (1.0 - 1.0 / Real(n)); }
Real texCoordToUnit(Real u, int n) { return (u - 0.5 / Real(n)) / (1.0 - 1.0 / Real(n)); }

// (r, mu) -> transmittance texture coordinates: x from the distance to the top boundary between
// its extremes for this r, y from the distance to the horizon (dense near the ground).
vec2 transmittanceUv(IN(AtmosphereParameters) atm, Real r, Real mu) {
  Real H = topHorizonDistance(atm);
  Real rho = safeSqrt(horizonDistanceSq(atm, r));
  Real d = distanceToTop(atm, r, mu);
  Real dMin = atm.topRadius - r;
  Real dMax = rho + H;
  Real xMu = dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0;
  return vec2(unitToTexCoord(xMu, atm.transmittanceWidth),
              unitToTexCoord(rho / H, atm.transmittanceHeight));
}
void transmittanceRMu(IN(AtmosphereParameters) atm, vec2 uv, OUT(Real) r, OUT(Real) mu) {
  Real H = topHorizonDistance(atm);
  Real rho = H * texCoordToUnit(uv.y, atm.transmittanceHeight);
  r = sqrt(rho * rho + atm.bottomRadius * atm.bottomRadius);
  Real dMin = atm.topRadius - r;
  Real dMax = rho + H;
  Real d = dMin + texCoordToUnit(uv.x, atm.transmittanceWidth) * (dMax - dMin);
  mu = d == 0.0 ? 1.0 : clampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
}

vec3 transmittanceToTop(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real mu) {
  return rgbOf(texture(tex, transmittanceUv(atm, r, mu)));
}
// Transmittance over distance d along the ray, as a ratio of two transmittances to the
// boundary (Eq. 5 is multiplicative along a ray); rays that hit the ground use the reversed ray.
vec3 transmittanceAlong(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real mu, Real d,
                        bool hitsGround) {
  Real rD = radiusAlong(atm, r, mu, d);
  Real muD = clampCosine((r * mu + d) / rD);
  vec3 tiny = vec3(1e-30);
  if (hitsGround)
    return min(transmittanceToTop(atm, tex, rD, -muD) /
                   max(transmittanceToTop(atm, tex, r, -mu), tiny), vec3(1.0));
  return min(transmittanceToTop(atm, tex, r, mu) / max(transmittanceToTop(atm, tex, rD, muD), tiny),
             vec3(1.0));
}
// Transmittance to the Sun times the visible fraction of its disc above the horizon (linear in
// the Sun's elevation across the disc, smoothed).
vec3 transmittanceToSun(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real muS) {
  Real sinH = atm.bottomRadius / r;
  Real cosH = -safeSqrt(horizonDistanceSq(atm, r)) / r;
  Real a = atm.sunAngularRadius * sinH;
  return transmittanceToTop(atm, tex, r, muS) * smoothstep(-a, a, muS - cosH);
}

// ---------------------------------------------------------------------------------------------
// Single scattering: Eq. 9 (in-scattering S[L]) applied to the direct sunlight L0 (Eq. 7),
// integrated along the view ray. Phase functions are left out (applied at lookup time).

void singleScatteringIntegrand(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real mu,
                               Real muS, Real nu, Real d, bool hitsGround, OUT(vec3) rayleigh,
                               OUT(vec3) mie) {
  Real rD = radiusAlong(atm, r, mu, d);
  Real muSD = clampCosine((r * muS + d * nu) / rD);
  vec3 t = transmittanceAlong(atm, tex, r, mu, d, hitsGround) * transmittanceToSun(atm, tex, rD, muSD);
  rayleigh = t * rayleighDensity(atm, rD - atm.bottomRadius);
  mie = t * mieDensity(atm, rD - atm.bottomRadius);
}

void computeSingleScattering(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real mu,
                             Real muS, Real nu, bool hitsGround, OUT(vec3) rayleigh,
                             OUT(vec3) mie) {
  Real dx = distanceToBoundary(atm, r, mu, hitsGround) / Real(SCATTERING_STEPS);
  vec3 sumR = vec3(0.0);
  vec3 sumM = vec3(0.0);
  for (int i = 0; i <= SCATTERING_STEPS; ++i) {
    vec3 ri = vec3(0.0);
    vec3 mi = vec3(0.0);
    singleScatteringIntegrand(atm, tex, r, mu, muS, nu, Real(i) * dx, hitsGround, ri, mi);
    Real w = (i == 0 || i == SCATTERING_STEPS) ? 0.5 : 1.0;
    sumR += ri * w;
    sumM += mi * w;
  }
  rayleigh = sumR * dx * atm.solarIrradiance * atm.rayleighScattering;
  mie = sumM * dx * atm.solarIrradiance * atm.mieScattering;
}

// ---------------------------------------------------------------------------------------------
// The 4D scattering tables (r, mu, mu_s, nu) packed in a 3D texture: x = nu-slice * MuS + mu_s,
// y = mu (lower half: rays hitting the ground), z = r.

// Paper Section 4: u_mu_s = (1 - exp(-3 mu_s - 0.6)) / (1 - exp(-3.6)), here with the lower bound
// muSMin (the paper's -0.2) as a parameter.
Real muSToUnit(IN(AtmosphereParameters) atm, Real muS) {
  Real x = (1.0 - exp(-3.0 * (muS - atm.muSMin))) / (1.0 - exp(-3.0 * (1.0 - atm.muSMin)));
  return clamp(x, Real(0.0), Real(1.0));
}
Real unitToMuS(IN(AtmosphereParameters) atm, Real x) {
  return atm.muSMin - log(1.0 - x * (1.0 - exp(-3.0 * (1.0 - atm.muSMin)))) / 3.0;
}

// Returns (u_nu, u_mu_s, u_mu, u_r).
vec4 scatteringUvwz(IN(AtmosphereParameters) atm, Real r, Real mu, Real muS, Real nu,
                    bool hitsGround) {
  Real H = topHorizonDistance(atm);
  Real rho = safeSqrt(horizonDistanceSq(atm, r));
  Real uR = unitToTexCoord(rho / H, atm.scatteringR);
  Real rMu = r * mu;
  Real disc = rMu * rMu - horizonDistanceSq(atm, r);
  Real uMu = 0.0;
  if (hitsGround) {
    // Distance to the ground, between r - bottom (straight down) and rho (horizon).
    Real d = -rMu - safeSqrt(disc);
    Real dMin = r - atm.bottomRadius;
    Real dMax = rho;
    Real x = dMax == dMin ? 0.0 : (d - dMin) / (dMax - dMin);
    uMu = 0.5 - 0.5 * unitToTexCoord(x, atm.scatteringMu / 2);
  } else {
    // Distance to the top, between top - r (straight up) and rho + H (horizon).
    Real d = -rMu + safeSqrt(disc + H * H);
    Real dMin = atm.topRadius - r;
    Real dMax = rho + H;
    uMu = 0.5 + 0.5 * unitToTexCoord((d - dMin) / (dMax - dMin), atm.scatteringMu / 2);
  }
  Real uMuS = unitToTexCoord(muSToUnit(atm, muS), atm.scatteringMuS);
  return vec4((nu + 1.0) / 2.0, uMuS, uMu, uR);
}

void scatteringRMuMuSNu(IN(AtmosphereParameters) atm, vec4 uvwz, OUT(Real) r, OUT(Real) mu,
                        OUT(Real) muS, OUT(Real) nu, OUT(bool) hitsGround) {
  Real H = topHorizonDistance(atm);
  Real rho = H * texCoordToUnit(uvwz.w, atm.scatteringR);
  r = sqrt(rho * rho + atm.bottomRadius * atm.bottomRadius);
  if (uvwz.z < 0.5) {
    Real dMin = r - atm.bottomRadius;
    Real dMax = rho;
    Real d = dMin + (dMax - dMin) * texCoordToUnit(1.0 - 2.0 * uvwz.z, atm.scatteringMu / 2);
    mu = d == 0.0 ? -1.0 : clampCosine(-(rho * rho + d * d) / (2.0 * r * d));
    hitsGround = true;
  } else {
    Real dMin = atm.topRadius - r;
    Real dMax = rho + H;
    Real d = dMin + (dMax - dMin) * texCoordToUnit(2.0 * uvwz.z - 1.0, atm.scatteringMu / 2);
    mu = d == 0.0 ? 1.0 : clampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
    hitsGround = false;
  }
  muS = unitToMuS(atm, texCoordToUnit(uvwz.y, atm.scatteringMuS));
  nu = clampCosine(uvwz.x * 2.0 - 1.0);
}

// Parameters of the texel whose centre is texelCentre (in texels) in the packed 3D texture.
void scatteringTexelParameters(IN(AtmosphereParameters) atm, vec3 texelCentre, OUT(Real) r,
                               OUT(Real) mu, OUT(Real) muS, OUT(Real) nu, OUT(bool) hitsGround) {
  Real sizeMuS = Real(atm.scatteringMuS);
  Real sliceNu = floor(texelCentre.x / sizeMuS);
  Real texelMuS = mod(texelCentre.x, sizeMuS);
  vec4 uvwz = vec4(sliceNu / Real(atm.scatteringNu - 1), texelMuS / sizeMuS,
                   texelCentre.y / Real(atm.scatteringMu), texelCentre.z / Real(atm.scatteringR));
  scatteringRMuMuSNu(atm, uvwz, r, mu, muS, nu, hitsGround);
  // Only nu within [cos(theta + theta_s), cos(theta - theta_s)] is geometrically possible.
  Real s = safeSqrt((1.0 - mu * mu) * (1.0 - muS * muS));
  nu = clamp(nu, mu * muS - s, mu * muS + s);
}

// Quadrilinear lookup: trilinear in (mu_s, mu, r) within two nu slices, blended linearly.
vec4 sampleScattering(IN(AtmosphereParameters) atm, IN(Texture3D) tex, Real r, Real mu, Real muS,
                      Real nu, bool hitsGround) {
  vec4 uvwz = scatteringUvwz(atm, r, mu, muS, nu, hitsGround);
  Real x = uvwz.x * Real(atm.scatteringNu - 1);
  Real slice = floor(x);
  Real f = x - slice;
  Real n = Real(atm.scatteringNu);
  vec4 a = texture(tex, vec3((slice + uvwz.y) / n, uvwz.z, uvwz.w));
  vec4 b = texture(tex, vec3((slice + 1.0 + uvwz.y) / n, uvwz.z, uvwz.w));
  return a * (1.0 - f) + b * f;
}

// ---------------------------------------------------------------------------------------------
// Ground irradiance E (Section 2.2, the irradiance integral behind R[L], Eq. 8), tabulated over
// (r, mu_s) for a horizontal surface. The direct part E[L0] is computed analytically when
// rendering; the table holds the indirect (sky) part.

vec2 irradianceUv(IN(AtmosphereParameters) atm, Real r, Real muS) {
  Real xR = (r - atm.bottomRadius) / (atm.topRadius - atm.bottomRadius);
  return vec2(unitToTexCoord(muS * 0.5 + 0.5, atm.irradianceWidth),
              unitToTexCoord(xR, atm.irradianceHeight));
}
void irradianceRMuS(IN(AtmosphereParameters) atm, vec2 uv, OUT(Real) r, OUT(Real) muS) {
  r = atm.bottomRadius +
      texCoordToUnit(uv.y, atm.irradianceHeight) * (atm.topRadius - atm.bottomRadius);
  muS = clampCosine(2.0 * texCoordToUnit(uv.x, atm.irradianceWidth) - 1.0);
}
vec3 sampleIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real muS) {
  return rgbOf(texture(tex, irradianceUv(atm, r, muS)));
}

// E[L0]: the attenuated Sun on a horizontal surface; the disc's mean cosine is used while it
// crosses the horizon.
vec3 computeDirectIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Real r, Real muS) {
  Real a = atm.sunAngularRadius;
  Real meanCos = muS < -a ? 0.0 : (muS > a ? muS : (muS + a) * (muS + a) / (4.0 * a));
  return atm.solarIrradiance * transmittanceToTop(atm, tex, r, muS) * meanCos;
}

// Radiance of scattering order `order` arriving at r from direction (mu, nu): order 1 from the
// single-scattering tables with their phase functions, higher orders from `multiple`.
vec3 scatteringOfOrder(IN(AtmosphereParameters) atm, IN(Texture3D) singleRayleigh,
                       IN(Texture3D) singleMie, IN(Texture3D) multiple, Real r, Real mu, Real muS,
                       Real nu, bool hitsGround, int order) {
  if (order == 1)
    return rgbOf(sampleScattering(atm, singleRayleigh, r, mu, muS, nu, hitsGround)) *
               rayleighPhase(nu) +
           rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hitsGround)) *
               miePhase(atm.miePhaseG, nu);
  return rgbOf(sampleScattering(atm, multiple, r, mu, muS, nu, hitsGround));
}

// E[L_order] on a horizontal surface at r: the hemisphere integral of radiance times cosine.
vec3 computeIndirectIrradiance(IN(AtmosphereParameters) atm, IN(Texture3D) singleRayleigh,
                               IN(Texture3D) singleMie, IN(Texture3D) multiple, Real r, Real muS,
                               int order) {
  int nTheta = atm.sphereSamples / 2;
  int nPhi = 4 * nTheta;
  Real dTheta = PI / 2.0 / Real(nTheta);
  Real dPhi = 2.0 * PI / Real(nPhi);
  vec3 sun = vec3(safeSqrt(1.0 - muS * muS), 0.0, muS);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < nTheta; ++j) {
    Real theta = (Real(j) + 0.5) * dTheta;
    for (int i = 0; i < nPhi; ++i) {
      Real phi = (Real(i) + 0.5) * dPhi;
      vec3 w = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      Real dOmega = dTheta * dPhi * sin(theta);
      sum += scatteringOfOrder(atm, singleRayleigh, singleMie, multiple, r, w.z, muS,
                               dot(w, sun), false, order) * (w.z * dOmega);
    }
  }
  return sum;
}

// Scattering density J of order `order` at (r, mu, mu_s, nu): the integrand of Eq. 9 (S[L]) with
// L = L_{order-1} (in-scattered light plus light reflected by the ground, Eq. 8, using the
// ground irradiance of order-2), integrated over the sphere of incident directions.
vec3 computeScatteringDensity(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                              IN(Texture3D) singleRayleigh, IN(Texture3D) singleMie,
                              IN(Texture3D) multiple, IN(Texture2D) irradiance, Real r, Real mu,
                              Real muS, Real nu, int order) {
  // Local frame: zenith +z, view direction in the x-z plane.
  vec3 view = vec3(safeSqrt(1.0 - mu * mu), 0.0, mu);
  Real sunX = view.x == 0.0 ? 0.0 : (nu - mu * muS) / view.x;
  vec3 sun = vec3(sunX, safeSqrt(1.0 - sunX * sunX - muS * muS), muS);
  int nTheta = atm.sphereSamples;
  int nPhi = 2 * nTheta;
  Real dTheta = PI / Real(nTheta);
  Real dPhi = 2.0 * PI / Real(nPhi);
  Real h = r - atm.bottomRadius;
  vec3 betaR = atm.rayleighScattering * rayleighDensity(atm, h);
  vec3 betaM = atm.mieScattering * mieDensity(atm, h);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < nTheta; ++j) {
    Real theta = (Real(j) + 0.5) * dTheta;
    Real cosTheta = cos(theta);
    Real sinTheta = sin(theta);
    bool hits = rayHitsGround(atm, r, cosTheta);
    Real groundDistance = 0.0;
    vec3 groundFactor = vec3(0.0);
    if (hits) {
      groundDistance = distanceToBottom(atm, r, cosTheta);
      groundFactor = transmittanceAlong(atm, transmittance, r, cosTheta, groundDistance, true) *
                     atm.groundAlbedo / PI;
    }
    for (int i = 0; i < nPhi; ++i) {
      Real phi = (Real(i) + 0.5) * dPhi;
      vec3 w = vec3(cos(phi) * sinTheta, sin(phi) * sinTheta, cosTheta);
      Real dOmega = dTheta * dPhi * sinTheta;
      vec3 incident = scatteringOfOrder(atm, singleRayleigh, singleMie, multiple, r, cosTheta,
                                        muS, dot(w, sun), hits, order - 1);
      if (hits) {
        vec3 groundPoint = vec3(0.0, 0.0, r) + w * groundDistance;
        vec3 normal = groundPoint / length(groundPoint);
        incident += groundFactor *
                    sampleIrradiance(atm, irradiance, atm.bottomRadius, dot(normal, sun));
      }
      Real nuI = dot(view, w);
      sum += incident * (betaR * rayleighPhase(nuI) + betaM * miePhase(atm.miePhaseG, nuI)) * dOmega;
    }
  }
  return sum;
}

// Multiple scattering of one order: the in-scattered density J integrated along the ray with
// the transmittance to the viewer (Eq. 9 again, its outer integral).
vec3 computeMultipleScattering(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                               IN(Texture3D) density, Real r, Real mu, Real muS, Real nu,
                               bool hitsGround) {
  Real dx = distanceToBoundary(atm, r, mu, hitsGround) / Real(SCATTERING_STEPS);
  vec3 sum = vec3(0.0);
  for (int i = 0; i <= SCATTERING_STEPS; ++i) {
    Real d = Real(i) * dx;
    Real rI = radiusAlong(atm, r, mu, d);
    Real muI = clampCosine((r * mu + d) / rI);
    Real muSI = clampCosine((r * muS + d * nu) / rI);
    vec3 j = rgbOf(sampleScattering(atm, density, rI, muI, muSI, nu, hitsGround));
    Real w = (i == 0 || i == SCATTERING_STEPS) ? 0.5 : 1.0;
    sum += j * transmittanceAlong(atm, transmittance, r, mu, d, hitsGround) * (w * dx);
  }
  return sum;
}

// ---------------------------------------------------------------------------------------------
// Rendering (Section 4, "rendering"): lookups into the final tables. `scattering` holds Rayleigh
// single scattering plus all multiple scattering divided by the Rayleigh phase function (rgb);
// `singleMie` holds single Mie scattering (rgb), both without phase functions.

// Moves a viewer above the atmosphere to where its ray enters it. Returns false when the ray
// misses the atmosphere; otherwise updates r, mu, muS and returns the distance travelled.
bool enterAtmosphere(IN(AtmosphereParameters) atm, INOUT(Real) r, INOUT(Real) mu, INOUT(Real) muS,
                     Real nu, OUT(Real) travelled) {
  travelled = 0.0;
  if (r <= atm.topRadius) return true;
  Real rMu = r * mu;
  Real disc = rMu * rMu - (r - atm.topRadius) * (r + atm.topRadius);
  if (disc < 0.0 || rMu >= 0.0) return false;
  travelled = -rMu - sqrt(disc);
  Real r0 = r;
  r = atm.topRadius;
  mu = clampCosine((rMu + travelled) / r);
  muS = clampCosine((r0 * muS + travelled * nu) / r);
  return true;
}

// In-scattered radiance along a ray to the atmosphere's boundary or the ground (the sky), and
// the ray's transmittance (0 when it hits the ground). The Sun's disc is not included.
vec3 skyRadiance(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                 IN(Texture3D) scattering, IN(Texture3D) singleMie, Real r, Real mu, Real muS,
                 Real nu, OUT(vec3) rayTransmittance) {
  rayTransmittance = vec3(1.0);
  Real travelled = 0.0;
  if (!enterAtmosphere(atm, r, mu, muS, nu, travelled)) return vec3(0.0);
  bool hits = rayHitsGround(atm, r, mu);
  rayTransmittance = hits ? vec3(0.0) : transmittanceToTop(atm, transmittance, r, mu);
  vec3 s = rgbOf(sampleScattering(atm, scattering, r, mu, muS, nu, hits));
  vec3 m = rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hits));
  return s * rayleighPhase(nu) + m * miePhase(atm.miePhaseG, nu);
}

// Aerial perspective: radiance in-scattered between the viewer and a point d metres along the
// ray, S[L](x) - T(x, x_d) S[L](x_d) (Section 4), and the transmittance T(x, x_d). With d past
// the atmosphere's boundary this is the sky (as skyRadiance, for rays that miss the ground).
vec3 skyRadianceToPoint(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                        IN(Texture3D) scattering, IN(Texture3D) singleMie, Real r, Real mu,
                        Real muS, Real nu, Real d, OUT(vec3) rayTransmittance) {
  rayTransmittance = vec3(1.0);
  Real travelled = 0.0;
  if (!enterAtmosphere(atm, r, mu, muS, nu, travelled)) return vec3(0.0);
  d = max(d - travelled, Real(0.0));
  bool hits = rayHitsGround(atm, r, mu);
  Real rP = radiusAlong(atm, r, mu, d);
  Real muP = clampCosine((r * mu + d) / rP);
  Real muSP = clampCosine((r * muS + d * nu) / rP);
  rayTransmittance = transmittanceAlong(atm, transmittance, r, mu, d, hits);
  vec3 s = rgbOf(sampleScattering(atm, scattering, r, mu, muS, nu, hits)) -
           rayTransmittance * rgbOf(sampleScattering(atm, scattering, rP, muP, muSP, nu, hits));
  vec3 m = rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hits)) -
           rayTransmittance * rgbOf(sampleScattering(atm, singleMie, rP, muP, muSP, nu, hits));
  // The difference of two nearly equal Mie terms is noise once the Sun has set (not an issue
  // when the point is on the top boundary, where the second term vanishes: d past the sky).
  if (rP < atm.topRadius - 1.0) m *= smoothstep(Real(0.0), Real(0.01), muS);
  return max(s, vec3(0.0)) * rayleighPhase(nu) + max(m, vec3(0.0)) * miePhase(atm.miePhaseG, nu);
}

// Light reaching a horizontal surface at radius r: returns the Sun's irradiance on a surface
// facing it (multiply by max(cos, 0) for another orientation) and the sky's irradiance on the
// horizontal surface in skyIrradiance.
vec3 sunAndSkyIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                         IN(Texture2D) irradiance, Real r, Real muS, OUT(vec3) skyIrradiance) {
  skyIrradiance = sampleIrradiance(atm, irradiance, r, muS);
  return atm.solarIrradiance * transmittanceToSun(atm, transmittance, r, muS);
}

// Radiance of the Sun's disc (units of solarIrradiance / sr): irradiance over its solid angle.
vec3 sunDiscRadiance(IN(AtmosphereParameters) atm) {
  return atm.solarIrradiance / (PI * atm.sunAngularRadius * atm.sunAngularRadius);
}
