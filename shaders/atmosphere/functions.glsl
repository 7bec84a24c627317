// Precomputed atmospheric scattering after Bruneton & Neyret 2008, "Precomputed Atmospheric
// Scattering" (EGSR 2008): the physics shared by the GPU passes and by the double-precision CPU
// reference. src/atmosphere/Reference.cpp compiles this very file as C++ with GLM types, so it is
// written in the common subset of GLSL 4.50 and C++20:
//   * types Number, vec2, vec3, vec4 (float/vec on the GPU, double/dvec on the CPU);
//   * parameters qualified IN(T) / OUT(T) / INOUT(T); no swizzles (rgbOf() instead); explicit Number(...)
//     conversions; no float suffixes; no include directives (the includer provides Number, PI, IN, OUT, INOUT,
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
  Number sunAngularRadius;    // radians
  Number bottomRadius;        // m, radius of the ground sphere of the tables
  Number topRadius;           // m, radius of the top of the atmosphere
  vec3 rayleighScattering;  // 1/m at altitude 0 (Eq. 1)
  Number rayleighScaleHeight; // m
  vec3 mieScattering;       // 1/m at altitude 0 (Eq. 3)
  vec3 mieExtinction;       // 1/m at altitude 0, scattering + absorption
  Number mieScaleHeight;      // m
  Number miePhaseG;           // Cornette-Shanks asymmetry, (-1, 1)
  vec3 ozoneAbsorption;     // 1/m at the ozone peak
  Number ozoneCenterAltitude; // m
  Number ozoneHalfWidth;      // m, the tent profile reaches 0 this far from the peak
  vec3 groundAlbedo;        // Lambertian ground of the tables, [0, 1]
  Number muSMin;              // lowest Sun zenith cosine stored in the scattering tables
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
Number clampCosine(Number mu) { return clamp(mu, Number(-1.0), Number(1.0)); }
Number safeSqrt(Number a) { return sqrt(max(a, Number(0.0))); }
Number clampRadius(IN(AtmosphereParameters) atm, Number r) {
  return clamp(r, atm.bottomRadius, atm.topRadius);
}

// ---------------------------------------------------------------------------------------------
// Geometry of a ray from radius r with view zenith cosine mu in the spherical shell.

// r^2 - bottom^2 factored so it stays accurate a few metres above the ground in float.
Number horizonDistanceSq(IN(AtmosphereParameters) atm, Number r) {
  return (r - atm.bottomRadius) * (r + atm.bottomRadius);
}
// Distance from the ground to the top boundary along a tangent ray, m.
Number topHorizonDistance(IN(AtmosphereParameters) atm) {
  return safeSqrt((atm.topRadius - atm.bottomRadius) * (atm.topRadius + atm.bottomRadius));
}
// Distance to the top boundary (|p + d v| = topRadius, far root), m.
Number distanceToTop(IN(AtmosphereParameters) atm, Number r, Number mu) {
  Number disc = (atm.topRadius - r) * (atm.topRadius + r) + r * r * mu * mu;
  return max(-r * mu + safeSqrt(disc), Number(0.0));
}
// Distance to the ground (near root), m; meaningful when rayHitsGround().
Number distanceToBottom(IN(AtmosphereParameters) atm, Number r, Number mu) {
  Number disc = r * r * mu * mu - horizonDistanceSq(atm, r);
  return max(-r * mu - safeSqrt(disc), Number(0.0));
}
bool rayHitsGround(IN(AtmosphereParameters) atm, Number r, Number mu) {
  return mu < 0.0 && r * r * mu * mu >= horizonDistanceSq(atm, r);
}
Number distanceToBoundary(IN(AtmosphereParameters) atm, Number r, Number mu, bool hitsGround) {
  return hitsGround ? distanceToBottom(atm, r, mu) : distanceToTop(atm, r, mu);
}
// Radius and zenith cosine at distance d along the ray.
Number radiusAlong(IN(AtmosphereParameters) atm, Number r, Number mu, Number d) {
  return clampRadius(atm, sqrt(d * d + 2.0 * r * mu * d + r * r));
}

// ---------------------------------------------------------------------------------------------
// Density profiles and extinction: Eq. 1 (Rayleigh) and Eq. 3 (Mie), both exponential in the
// altitude h; ozone (not in the 2008 paper) absorbs only, with a tent profile.

Number rayleighDensity(IN(AtmosphereParameters) atm, Number h) {
  return clamp(exp(-h / atm.rayleighScaleHeight), Number(0.0), Number(1.0));
}
Number mieDensity(IN(AtmosphereParameters) atm, Number h) {
  return clamp(exp(-h / atm.mieScaleHeight), Number(0.0), Number(1.0));
}
Number ozoneDensity(IN(AtmosphereParameters) atm, Number h) {
  return max(1.0 - abs(h - atm.ozoneCenterAltitude) / atm.ozoneHalfWidth, Number(0.0));
}
// beta_e(h) = beta_R^s(h) + beta_M^e(h) + beta_O^a(h), 1/m.
vec3 extinctionAt(IN(AtmosphereParameters) atm, Number h) {
  return atm.rayleighScattering * rayleighDensity(atm, h) +
         atm.mieExtinction * mieDensity(atm, h) + atm.ozoneAbsorption * ozoneDensity(atm, h);
}

// Phase functions: Rayleigh (Eq. 2) and Cornette-Shanks for Mie (Eq. 4), 1/sr.
Number rayleighPhase(Number nu) { return 3.0 / (16.0 * PI) * (1.0 + nu * nu); }
Number miePhase(Number g, Number nu) {
  Number k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / pow(max(1.0 + g * g - 2.0 * g * nu, Number(1e-6)), Number(1.5));
}

// ---------------------------------------------------------------------------------------------
// Transmittance, Eq. 5: T(x, y) = exp(-integral of beta_e over [x, y]), to the top boundary,
// by the trapezoidal rule.

vec3 computeTransmittanceToTop(IN(AtmosphereParameters) atm, Number r, Number mu) {
  Number dx = distanceToTop(atm, r, mu) / Number(TRANSMITTANCE_STEPS);
  vec3 depth = vec3(0.0);
  for (int i = 0; i <= TRANSMITTANCE_STEPS; ++i) {
    Number di = Number(i) * dx;
    Number hi = sqrt(di * di + 2.0 * r * mu * di + r * r) - atm.bottomRadius;
    Number w = (i == 0 || i == TRANSMITTANCE_STEPS) ? 0.5 : 1.0;
    depth += extinctionAt(atm, hi) * (w * dx);
  }
  return exp(-depth);
}

// Texture coordinates in [0.5/n, 1 - 0.5/n] so texel centres hold the end points.
Number unitToTexCoord(Number x, int n) { return 0.5 / Number(n) + x * (1.0 - 1.0 / Number(n)); }
Number texCoordToUnit(Number u, int n) { return (u - 0.5 / Number(n)) / (1.0 - 1.0 / Number(n)); }

// (r, mu) -> transmittance texture coordinates: x from the distance to the top boundary between
// its extremes for this r, y from the distance to the horizon (dense near the ground).
vec2 transmittanceUv(IN(AtmosphereParameters) atm, Number r, Number mu) {
  Number H = topHorizonDistance(atm);
  Number rho = safeSqrt(horizonDistanceSq(atm, r));
  Number d = distanceToTop(atm, r, mu);
  Number dMin = atm.topRadius - r;
  Number dMax = rho + H;
  Number xMu = dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0;
  return vec2(unitToTexCoord(xMu, atm.transmittanceWidth),
              unitToTexCoord(rho / H, atm.transmittanceHeight));
}
void transmittanceRMu(IN(AtmosphereParameters) atm, vec2 uv, OUT(Number) r, OUT(Number) mu) {
  Number H = topHorizonDistance(atm);
  Number rho = H * texCoordToUnit(uv.y, atm.transmittanceHeight);
  r = sqrt(rho * rho + atm.bottomRadius * atm.bottomRadius);
  Number dMin = atm.topRadius - r;
  Number dMax = rho + H;
  Number d = dMin + texCoordToUnit(uv.x, atm.transmittanceWidth) * (dMax - dMin);
  mu = d == 0.0 ? 1.0 : clampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
}

vec3 transmittanceToTop(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number mu) {
  return rgbOf(texture(tex, transmittanceUv(atm, r, mu)));
}
// Transmittance over distance d along the ray, as a ratio of two transmittances to the
// boundary (Eq. 5 is multiplicative along a ray); rays that hit the ground use the reversed ray.
vec3 transmittanceAlong(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number mu, Number d,
                        bool hitsGround) {
  Number rD = radiusAlong(atm, r, mu, d);
  Number muD = clampCosine((r * mu + d) / rD);
  vec3 tiny = vec3(1e-30);
  if (hitsGround)
    return min(transmittanceToTop(atm, tex, rD, -muD) /
                   max(transmittanceToTop(atm, tex, r, -mu), tiny), vec3(1.0));
  return min(transmittanceToTop(atm, tex, r, mu) / max(transmittanceToTop(atm, tex, rD, muD), tiny),
             vec3(1.0));
}
// Transmittance to the Sun times the visible fraction of its disc above the horizon (linear in
// the Sun's elevation across the disc, smoothed).
vec3 transmittanceToSun(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number muS) {
  Number sinH = atm.bottomRadius / r;
  Number cosH = -safeSqrt(horizonDistanceSq(atm, r)) / r;
  Number a = atm.sunAngularRadius * sinH;
  return transmittanceToTop(atm, tex, r, muS) * smoothstep(-a, a, muS - cosH);
}

// ---------------------------------------------------------------------------------------------
// Single scattering: Eq. 9 (in-scattering S[L]) applied to the direct sunlight L0 (Eq. 7),
// integrated along the view ray. Phase functions are left out (applied at lookup time).

void singleScatteringIntegrand(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number mu,
                               Number muS, Number nu, Number d, bool hitsGround, OUT(vec3) rayleigh,
                               OUT(vec3) mie) {
  Number rD = radiusAlong(atm, r, mu, d);
  Number muSD = clampCosine((r * muS + d * nu) / rD);
  vec3 t = transmittanceAlong(atm, tex, r, mu, d, hitsGround) * transmittanceToSun(atm, tex, rD, muSD);
  rayleigh = t * rayleighDensity(atm, rD - atm.bottomRadius);
  mie = t * mieDensity(atm, rD - atm.bottomRadius);
}

void computeSingleScattering(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number mu,
                             Number muS, Number nu, bool hitsGround, OUT(vec3) rayleigh,
                             OUT(vec3) mie) {
  Number dx = distanceToBoundary(atm, r, mu, hitsGround) / Number(SCATTERING_STEPS);
  vec3 sumR = vec3(0.0);
  vec3 sumM = vec3(0.0);
  for (int i = 0; i <= SCATTERING_STEPS; ++i) {
    vec3 ri = vec3(0.0);
    vec3 mi = vec3(0.0);
    singleScatteringIntegrand(atm, tex, r, mu, muS, nu, Number(i) * dx, hitsGround, ri, mi);
    Number w = (i == 0 || i == SCATTERING_STEPS) ? 0.5 : 1.0;
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
Number muSToUnit(IN(AtmosphereParameters) atm, Number muS) {
  Number x = (1.0 - exp(-3.0 * (muS - atm.muSMin))) / (1.0 - exp(-3.0 * (1.0 - atm.muSMin)));
  return clamp(x, Number(0.0), Number(1.0));
}
Number unitToMuS(IN(AtmosphereParameters) atm, Number x) {
  return atm.muSMin - log(1.0 - x * (1.0 - exp(-3.0 * (1.0 - atm.muSMin)))) / 3.0;
}

// Returns (u_nu, u_mu_s, u_mu, u_r).
vec4 scatteringUvwz(IN(AtmosphereParameters) atm, Number r, Number mu, Number muS, Number nu,
                    bool hitsGround) {
  Number H = topHorizonDistance(atm);
  Number rho = safeSqrt(horizonDistanceSq(atm, r));
  Number uR = unitToTexCoord(rho / H, atm.scatteringR);
  Number rMu = r * mu;
  Number disc = rMu * rMu - horizonDistanceSq(atm, r);
  Number uMu = 0.0;
  if (hitsGround) {
    // Distance to the ground, between r - bottom (straight down) and rho (horizon).
    Number d = -rMu - safeSqrt(disc);
    Number dMin = r - atm.bottomRadius;
    Number dMax = rho;
    Number x = dMax == dMin ? 0.0 : (d - dMin) / (dMax - dMin);
    uMu = 0.5 - 0.5 * unitToTexCoord(x, atm.scatteringMu / 2);
  } else {
    // Distance to the top, between top - r (straight up) and rho + H (horizon).
    Number d = -rMu + safeSqrt(disc + H * H);
    Number dMin = atm.topRadius - r;
    Number dMax = rho + H;
    uMu = 0.5 + 0.5 * unitToTexCoord((d - dMin) / (dMax - dMin), atm.scatteringMu / 2);
  }
  Number uMuS = unitToTexCoord(muSToUnit(atm, muS), atm.scatteringMuS);
  return vec4((nu + 1.0) / 2.0, uMuS, uMu, uR);
}

void scatteringRMuMuSNu(IN(AtmosphereParameters) atm, vec4 uvwz, OUT(Number) r, OUT(Number) mu,
                        OUT(Number) muS, OUT(Number) nu, OUT(bool) hitsGround) {
  Number H = topHorizonDistance(atm);
  Number rho = H * texCoordToUnit(uvwz.w, atm.scatteringR);
  r = sqrt(rho * rho + atm.bottomRadius * atm.bottomRadius);
  if (uvwz.z < 0.5) {
    Number dMin = r - atm.bottomRadius;
    Number dMax = rho;
    Number d = dMin + (dMax - dMin) * texCoordToUnit(1.0 - 2.0 * uvwz.z, atm.scatteringMu / 2);
    mu = d == 0.0 ? -1.0 : clampCosine(-(rho * rho + d * d) / (2.0 * r * d));
    hitsGround = true;
  } else {
    Number dMin = atm.topRadius - r;
    Number dMax = rho + H;
    Number d = dMin + (dMax - dMin) * texCoordToUnit(2.0 * uvwz.z - 1.0, atm.scatteringMu / 2);
    mu = d == 0.0 ? 1.0 : clampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
    hitsGround = false;
  }
  muS = unitToMuS(atm, texCoordToUnit(uvwz.y, atm.scatteringMuS));
  nu = clampCosine(uvwz.x * 2.0 - 1.0);
}

// Parameters of the texel whose centre is texelCentre (in texels) in the packed 3D texture.
void scatteringTexelParameters(IN(AtmosphereParameters) atm, vec3 texelCentre, OUT(Number) r,
                               OUT(Number) mu, OUT(Number) muS, OUT(Number) nu, OUT(bool) hitsGround) {
  Number sizeMuS = Number(atm.scatteringMuS);
  Number sliceNu = floor(texelCentre.x / sizeMuS);
  Number texelMuS = mod(texelCentre.x, sizeMuS);
  vec4 uvwz = vec4(sliceNu / Number(atm.scatteringNu - 1), texelMuS / sizeMuS,
                   texelCentre.y / Number(atm.scatteringMu), texelCentre.z / Number(atm.scatteringR));
  scatteringRMuMuSNu(atm, uvwz, r, mu, muS, nu, hitsGround);
  // Only nu within [cos(theta + theta_s), cos(theta - theta_s)] is geometrically possible.
  Number s = safeSqrt((1.0 - mu * mu) * (1.0 - muS * muS));
  nu = clamp(nu, mu * muS - s, mu * muS + s);
}

// Quadrilinear lookup: trilinear in (mu_s, mu, r) within two nu slices, blended linearly.
vec4 sampleScattering(IN(AtmosphereParameters) atm, IN(Texture3D) tex, Number r, Number mu, Number muS,
                      Number nu, bool hitsGround) {
  vec4 uvwz = scatteringUvwz(atm, r, mu, muS, nu, hitsGround);
  Number x = uvwz.x * Number(atm.scatteringNu - 1);
  Number slice = floor(x);
  Number f = x - slice;
  Number n = Number(atm.scatteringNu);
  vec4 a = texture(tex, vec3((slice + uvwz.y) / n, uvwz.z, uvwz.w));
  vec4 b = texture(tex, vec3((slice + 1.0 + uvwz.y) / n, uvwz.z, uvwz.w));
  return a * (1.0 - f) + b * f;
}

// ---------------------------------------------------------------------------------------------
// Ground irradiance E (Section 2.2, the irradiance integral behind R[L], Eq. 8), tabulated over
// (r, mu_s) for a horizontal surface. The direct part E[L0] is computed analytically when
// rendering; the table holds the indirect (sky) part.

vec2 irradianceUv(IN(AtmosphereParameters) atm, Number r, Number muS) {
  Number xR = (r - atm.bottomRadius) / (atm.topRadius - atm.bottomRadius);
  return vec2(unitToTexCoord(muS * 0.5 + 0.5, atm.irradianceWidth),
              unitToTexCoord(xR, atm.irradianceHeight));
}
void irradianceRMuS(IN(AtmosphereParameters) atm, vec2 uv, OUT(Number) r, OUT(Number) muS) {
  r = atm.bottomRadius +
      texCoordToUnit(uv.y, atm.irradianceHeight) * (atm.topRadius - atm.bottomRadius);
  muS = clampCosine(2.0 * texCoordToUnit(uv.x, atm.irradianceWidth) - 1.0);
}
vec3 sampleIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number muS) {
  return rgbOf(texture(tex, irradianceUv(atm, r, muS)));
}

// E[L0]: the attenuated Sun on a horizontal surface; the disc's mean cosine is used while it
// crosses the horizon.
vec3 computeDirectIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) tex, Number r, Number muS) {
  Number a = atm.sunAngularRadius;
  Number meanCos = muS < -a ? 0.0 : (muS > a ? muS : (muS + a) * (muS + a) / (4.0 * a));
  return atm.solarIrradiance * transmittanceToTop(atm, tex, r, muS) * meanCos;
}

// Radiance of scattering order `order` arriving at r from direction (mu, nu): order 1 from the
// single-scattering tables with their phase functions, higher orders from `multiple`.
vec3 scatteringOfOrder(IN(AtmosphereParameters) atm, IN(Texture3D) singleRayleigh,
                       IN(Texture3D) singleMie, IN(Texture3D) multiple, Number r, Number mu, Number muS,
                       Number nu, bool hitsGround, int order) {
  if (order == 1)
    return rgbOf(sampleScattering(atm, singleRayleigh, r, mu, muS, nu, hitsGround)) *
               rayleighPhase(nu) +
           rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hitsGround)) *
               miePhase(atm.miePhaseG, nu);
  return rgbOf(sampleScattering(atm, multiple, r, mu, muS, nu, hitsGround));
}

// E[L_order] on a horizontal surface at r: the hemisphere integral of radiance times cosine.
vec3 computeIndirectIrradiance(IN(AtmosphereParameters) atm, IN(Texture3D) singleRayleigh,
                               IN(Texture3D) singleMie, IN(Texture3D) multiple, Number r, Number muS,
                               int order) {
  int nTheta = atm.sphereSamples / 2;
  int nPhi = 4 * nTheta;
  Number dTheta = PI / 2.0 / Number(nTheta);
  Number dPhi = 2.0 * PI / Number(nPhi);
  vec3 sun = vec3(safeSqrt(1.0 - muS * muS), 0.0, muS);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < nTheta; ++j) {
    Number theta = (Number(j) + 0.5) * dTheta;
    for (int i = 0; i < nPhi; ++i) {
      Number phi = (Number(i) + 0.5) * dPhi;
      vec3 w = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      Number dOmega = dTheta * dPhi * sin(theta);
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
                              IN(Texture3D) multiple, IN(Texture2D) irradiance, Number r, Number mu,
                              Number muS, Number nu, int order) {
  // Local frame: zenith +z, view direction in the x-z plane.
  vec3 view = vec3(safeSqrt(1.0 - mu * mu), 0.0, mu);
  Number sunX = view.x == 0.0 ? 0.0 : (nu - mu * muS) / view.x;
  vec3 sun = vec3(sunX, safeSqrt(1.0 - sunX * sunX - muS * muS), muS);
  int nTheta = atm.sphereSamples;
  int nPhi = 2 * nTheta;
  Number dTheta = PI / Number(nTheta);
  Number dPhi = 2.0 * PI / Number(nPhi);
  Number h = r - atm.bottomRadius;
  vec3 betaR = atm.rayleighScattering * rayleighDensity(atm, h);
  vec3 betaM = atm.mieScattering * mieDensity(atm, h);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < nTheta; ++j) {
    Number theta = (Number(j) + 0.5) * dTheta;
    Number cosTheta = cos(theta);
    Number sinTheta = sin(theta);
    bool hits = rayHitsGround(atm, r, cosTheta);
    Number groundDistance = 0.0;
    vec3 groundFactor = vec3(0.0);
    if (hits) {
      groundDistance = distanceToBottom(atm, r, cosTheta);
      groundFactor = transmittanceAlong(atm, transmittance, r, cosTheta, groundDistance, true) *
                     atm.groundAlbedo / PI;
    }
    for (int i = 0; i < nPhi; ++i) {
      Number phi = (Number(i) + 0.5) * dPhi;
      vec3 w = vec3(cos(phi) * sinTheta, sin(phi) * sinTheta, cosTheta);
      Number dOmega = dTheta * dPhi * sinTheta;
      vec3 incident = scatteringOfOrder(atm, singleRayleigh, singleMie, multiple, r, cosTheta,
                                        muS, dot(w, sun), hits, order - 1);
      if (hits) {
        vec3 groundPoint = vec3(0.0, 0.0, r) + w * groundDistance;
        vec3 normal = groundPoint / length(groundPoint);
        incident += groundFactor *
                    sampleIrradiance(atm, irradiance, atm.bottomRadius, dot(normal, sun));
      }
      Number nuI = dot(view, w);
      sum += incident * (betaR * rayleighPhase(nuI) + betaM * miePhase(atm.miePhaseG, nuI)) * dOmega;
    }
  }
  return sum;
}

// Multiple scattering of one order: the in-scattered density J integrated along the ray with
// the transmittance to the viewer (Eq. 9 again, its outer integral).
vec3 computeMultipleScattering(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                               IN(Texture3D) density, Number r, Number mu, Number muS, Number nu,
                               bool hitsGround) {
  Number dx = distanceToBoundary(atm, r, mu, hitsGround) / Number(SCATTERING_STEPS);
  vec3 sum = vec3(0.0);
  for (int i = 0; i <= SCATTERING_STEPS; ++i) {
    Number d = Number(i) * dx;
    Number rI = radiusAlong(atm, r, mu, d);
    Number muI = clampCosine((r * mu + d) / rI);
    Number muSI = clampCosine((r * muS + d * nu) / rI);
    vec3 j = rgbOf(sampleScattering(atm, density, rI, muI, muSI, nu, hitsGround));
    Number w = (i == 0 || i == SCATTERING_STEPS) ? 0.5 : 1.0;
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
bool enterAtmosphere(IN(AtmosphereParameters) atm, INOUT(Number) r, INOUT(Number) mu, INOUT(Number) muS,
                     Number nu, OUT(Number) travelled) {
  travelled = 0.0;
  if (r <= atm.topRadius) return true;
  Number rMu = r * mu;
  Number disc = rMu * rMu - (r - atm.topRadius) * (r + atm.topRadius);
  if (disc < 0.0 || rMu >= 0.0) return false;
  travelled = -rMu - sqrt(disc);
  Number r0 = r;
  r = atm.topRadius;
  mu = clampCosine((rMu + travelled) / r);
  muS = clampCosine((r0 * muS + travelled * nu) / r);
  return true;
}

// In-scattered radiance along a ray to the atmosphere's boundary or the ground (the sky), and
// the ray's transmittance (0 when it hits the ground). The Sun's disc is not included.
vec3 skyRadiance(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                 IN(Texture3D) scattering, IN(Texture3D) singleMie, Number r, Number mu, Number muS,
                 Number nu, OUT(vec3) rayTransmittance) {
  rayTransmittance = vec3(1.0);
  Number travelled = 0.0;
  if (!enterAtmosphere(atm, r, mu, muS, nu, travelled)) return vec3(0.0);
  bool hits = rayHitsGround(atm, r, mu);
  rayTransmittance = hits ? vec3(0.0) : transmittanceToTop(atm, transmittance, r, mu);
  vec3 s = rgbOf(sampleScattering(atm, scattering, r, mu, muS, nu, hits));
  vec3 m = rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hits));
  return s * rayleighPhase(nu) + m * miePhase(atm.miePhaseG, nu);
}

// Aerial perspective without its phase functions: the Rayleigh (and multiple) and the single
// Mie radiance in-scattered between the viewer and a point d metres along the ray, each to be
// multiplied by its phase function of nu (skyRadianceToPoint), and the transmittance T(x, x_d).
// What render/aerial_table.comp tabulates.
void aerialScatteringToPoint(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                             IN(Texture3D) scattering, IN(Texture3D) singleMie, Number r, Number mu,
                             Number muS, Number nu, Number d, OUT(vec3) rayTransmittance,
                             OUT(vec3) rayleigh, OUT(vec3) mie) {
  rayTransmittance = vec3(1.0);
  rayleigh = vec3(0.0);
  mie = vec3(0.0);
  Number travelled = 0.0;
  if (!enterAtmosphere(atm, r, mu, muS, nu, travelled)) return;
  d = max(d - travelled, Number(0.0));
  bool hits = rayHitsGround(atm, r, mu);
  Number rP = radiusAlong(atm, r, mu, d);
  Number muP = clampCosine((r * mu + d) / rP);
  Number muSP = clampCosine((r * muS + d * nu) / rP);
  rayTransmittance = transmittanceAlong(atm, transmittance, r, mu, d, hits);
  vec3 s = rgbOf(sampleScattering(atm, scattering, r, mu, muS, nu, hits)) -
           rayTransmittance * rgbOf(sampleScattering(atm, scattering, rP, muP, muSP, nu, hits));
  vec3 m = rgbOf(sampleScattering(atm, singleMie, r, mu, muS, nu, hits)) -
           rayTransmittance * rgbOf(sampleScattering(atm, singleMie, rP, muP, muSP, nu, hits));
  // The difference of two nearly equal Mie terms is noise once the Sun has set (not an issue
  // when the point is on the top boundary, where the second term vanishes: d past the sky).
  if (rP < atm.topRadius - 1.0) m *= smoothstep(Number(0.0), Number(0.01), muS);
  rayleigh = max(s, vec3(0.0));
  mie = max(m, vec3(0.0));
}

// Aerial perspective: radiance in-scattered between the viewer and a point d metres along the
// ray, S[L](x) - T(x, x_d) S[L](x_d) (Section 4), and the transmittance T(x, x_d). With d past
// the atmosphere's boundary this is the sky (as skyRadiance, for rays that miss the ground).
vec3 skyRadianceToPoint(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                        IN(Texture3D) scattering, IN(Texture3D) singleMie, Number r, Number mu,
                        Number muS, Number nu, Number d, OUT(vec3) rayTransmittance) {
  vec3 rayleigh, mie;
  aerialScatteringToPoint(atm, transmittance, scattering, singleMie, r, mu, muS, nu, d, rayTransmittance, rayleigh, mie);
  return rayleigh * rayleighPhase(nu) + mie * miePhase(atm.miePhaseG, nu);
}

// Light reaching a horizontal surface at radius r: returns the Sun's irradiance on a surface
// facing it (multiply by max(cos, 0) for another orientation) and the sky's irradiance on the
// horizontal surface in skyIrradiance.
vec3 sunAndSkyIrradiance(IN(AtmosphereParameters) atm, IN(Texture2D) transmittance,
                         IN(Texture2D) irradiance, Number r, Number muS, OUT(vec3) skyIrradiance) {
  skyIrradiance = sampleIrradiance(atm, irradiance, r, muS);
  return atm.solarIrradiance * transmittanceToSun(atm, transmittance, r, muS);
}

// Radiance of the Sun's disc (units of solarIrradiance / sr): irradiance over its solid angle.
vec3 sunDiscRadiance(IN(AtmosphereParameters) atm) {
  return atm.solarIrradiance / (PI * atm.sunAngularRadius * atm.sunAngularRadius);
}
