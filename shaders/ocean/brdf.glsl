// Sea-surface reflectance of Bruneton, Neyret & Holzschuch 2010 (seed 000, §4-5): the Ross et
// al. BRDF for a Gaussian distribution of unresolved slopes, its Smith masking term, and the
// effective Fresnel factor for sky light filtered over the slope distribution.
//
// Shared by GLSL and C++ (src/ocean/Brdf.cpp compiles it with Number = double and GLM vectors),
// so CPU tests check the shaders' own code. Common subset only: Number, vec2, vec3, exp, sqrt,
// pow, max, min, clamp, dot, normalize.
//
// Conventions: all vectors unit, in one frame; n is the mean (resolved) surface normal; tx, ty
// the unit tangents along and across the wind; sigma2 = (sigma_x², sigma_y²) the unresolved
// slope variances along tx, ty (dimensionless, > 0).

const Number BRDF_PI = 3.14159265358979;
const Number BRDF_R0 = 0.02;  // water's Fresnel reflectance at normal incidence

// Schlick's Fresnel approximation F(x) = R + (1 - R)(1 - x)^5 (Eq. 6 context).
Number fresnelSchlick(Number cosTheta) {
  Number x = 1.0 - clamp(cosTheta, 0.0, 1.0);
  return BRDF_R0 + (1.0 - BRDF_R0) * x * x * x * x * x;
}

// erfc by a rational approximation (abs. error < 2e-3), enough for the masking term.
Number brdfErfc(Number x) {
  return 2.0 * exp(-x * x) / (2.319 * x + sqrt(4.0 + 1.52 * x * x));
}

// Smith's Lambda for a Gaussian slope distribution (Eq. 5):
// Lambda(a) = (exp(-a²) - a sqrt(pi) erfc(a)) / (2 a sqrt(pi)), a = 1 / (sqrt(2 sigma_phi²) tan(theta)),
// sigma_phi² the slope variance in the azimuth of the direction.
Number smithLambda(Number cosTheta, Number sigmaPhi2) {
  Number c = clamp(cosTheta, 1e-4, 0.99999);
  Number a = c / sqrt(2.0 * sigmaPhi2 * (1.0 - c * c));
  return max(0.0, (exp(-a * a) - a * sqrt(BRDF_PI) * brdfErfc(a)) / (2.0 * a * sqrt(BRDF_PI)));
}

// Slope variance in the azimuth of direction d: sigma_phi² = sx² cos²phi + sy² sin²phi.
Number azimuthVariance(vec3 d, vec3 tx, vec3 ty, vec2 sigma2) {
  Number x = dot(d, tx), y = dot(d, ty);
  Number r2 = max(x * x + y * y, 1e-12);
  return (sigma2.x * x * x + sigma2.y * y * y) / r2;
}

// Gaussian slope density p(zeta) = exp(-1/2 (zx²/sx² + zy²/sy²)) / (2 pi sx sy) (Eq. 3 context).
Number slopeDensity(vec2 zeta, vec2 sigma2) {
  Number e = 0.5 * (zeta.x * zeta.x / sigma2.x + zeta.y * zeta.y / sigma2.y);
  return exp(-e) / (2.0 * BRDF_PI * sqrt(sigma2.x * sigma2.y));
}

// Ross BRDF times cos(theta_l) for the Sun (Eq. 6 with the Sun's solid angle folded into the
// irradiance): radiance = sunIrradiance * rossSun(...).
// I = p(zeta_h) F(v.h) / (4 (h.n)^4 cos(theta_v) (1 + Lambda(a_v) + Lambda(a_l))).
Number rossSun(vec3 v, vec3 l, vec3 n, vec3 tx, vec3 ty, vec2 sigma2) {
  Number cosV = dot(v, n);
  Number cosL = dot(l, n);
  if (cosL <= 0.0 || cosV <= 0.0) return 0.0;
  vec3 h = normalize(v + l);
  Number hn = max(dot(h, n), 1e-4);
  vec2 zeta = vec2(-dot(h, tx) / hn, -dot(h, ty) / hn);  // slope of the facet normal h
  Number masking = 1.0 + smithLambda(cosV, azimuthVariance(v, tx, ty, sigma2)) +
                   smithLambda(cosL, azimuthVariance(l, tx, ty, sigma2));
  Number hn2 = hn * hn;
  return slopeDensity(zeta, sigma2) * fresnelSchlick(dot(v, h)) / (4.0 * hn2 * hn2 * cosV * masking);
}

// Effective Fresnel for light from the whole sky (Eq. 10, fitted in the paper):
// F_bar = R + (1 - R) (1 - cos theta_v)^(5 exp(-2.69 sigma_v)) / (1 + 22.7 sigma_v^1.5),
// sigma_v = sqrt(sigma_phi²) in the azimuth of v.
Number effectiveFresnel(Number cosV, Number sigmaV) {
  Number x = 1.0 - clamp(cosV, 0.0, 1.0);
  return BRDF_R0 + (1.0 - BRDF_R0) * pow(x, 5.0 * exp(-2.69 * sigmaV)) /
                       (1.0 + 22.7 * sigmaV * sqrt(sigmaV));  // sigma^1.5 without a pow
}

// Reflected direction for the facet of slope zeta (used for the filtered sky lookup, §5.2):
// f = normalize(-zeta_x tx - zeta_y ty + n), r = 2 (f.v) f - v.
vec3 reflectedBySlope(vec3 v, vec3 n, vec3 tx, vec3 ty, vec2 zeta) {
  vec3 f = normalize(n - zeta.x * tx - zeta.y * ty);
  return 2.0 * dot(f, v) * f - v;
}

// Stereographic projection used by the sky maps: u = [rx, ry] / (1 + rz) in the local frame
// (x east, y north, z up): zenith at 0, horizon on the unit circle.
vec2 stereographic(vec3 r) {
  return vec2(r.x, r.y) / (1.0 + max(r.z, -0.999));
}

// Principal axes of a slope covariance (xx, yy, xy) given in the (tx, ty) frame: the variances
// sigma2 along the axes (largest first, >= 0) and the first axis as (cos, sin) in (tx, ty).
// Lets the axis-aligned Ross BRDF above take any covariance, e.g. resolved slopes carried in
// the local wind's frame with their cross term (Bruneton 2010 Eq. 4 keeps the full matrix).
struct SlopeFrame {
  vec2 sigma2;
  vec2 axis;
};
SlopeFrame slopePrincipalAxes(vec3 cov) {
  Number a = cov.x, b = cov.y, c = cov.z;
  Number mean = 0.5 * (a + b);
  Number radius = sqrt(0.25 * (a - b) * (a - b) + c * c);
  SlopeFrame f;
  f.sigma2 = vec2(max(mean + radius, 0.0), max(mean - radius, 0.0));
  // Eigenvector of the largest eigenvalue, from the better-conditioned row.
  vec2 e = a >= b ? vec2(f.sigma2.x - b, c) : vec2(c, f.sigma2.x - a);
  Number len2 = dot(e, e);
  f.axis = len2 > 1e-30 ? e / sqrt(len2) : vec2(1.0, 0.0);
  return f;
}

// Covariance (xx, yy, xy) in the (tx, ty) frame of a 2x2 diagonal one (d.x along axis, d.y
// across), axis = (cos, sin) in (tx, ty).
vec3 covarianceFromAxes(vec2 d, vec2 axis) {
  Number c = axis.x, s = axis.y;
  return vec3(c * c * d.x + s * s * d.y, s * s * d.x + c * c * d.y, c * s * (d.x - d.y));
}

// The Sun's disc as a slope covariance, to add to the facets' (a convolution: the Sun's glint
// through a Gaussian facet distribution becomes the disc's reflection). A disc of angular
// radius alpha has per-axis angular variance alpha²/4. A facet reflects l into v when its
// normal is h = (v + l)/|v + l|; moving l by dl moves h by the part of dl normal to h over
// |v + l| = 2 (v.h): by 1/2 dl in the plane of incidence, by 1/(2 v.h) across it. Hence the
// facet slope variance that the disc spans: alpha²/16 in the plane of incidence and
// alpha²/(16 (v.h)²) across (slopes ~ tilts for the near-normal h of a glint). Returned in the
// (tx, ty) frame.
vec3 sunDiscSlopeCovariance(vec3 v, vec3 l, vec3 tx, vec3 ty, Number alpha) {
  vec3 h = normalize(v + l);
  Number vh = max(dot(v, h), 0.05);
  vec2 d = vec2(dot(l - v, tx), dot(l - v, ty));  // the plane of incidence, in the tangent plane
  Number len2 = dot(d, d);
  vec2 axis = len2 > 1e-12 ? d / sqrt(len2) : vec2(1.0, 0.0);
  Number inPlane = alpha * alpha / 16.0;
  return covarianceFromAxes(vec2(inPlane, inPlane / (vh * vh)), axis);
}

// The slopes the eye sees along the view's azimuth: a facet of slope zeta (towards the eye's
// side, in units of that azimuth's sigma) covers a share of the pixel proportional to its area
// projected towards the eye, 1 - zeta / k with k = cot(theta_v) / sigma_phi, and none beyond k
// (it faces away). Mean and variance of that weighted Gaussian, in units of sigma and sigma²
// (phi, Phi: the unit normal's density and distribution):
// M0 = Phi(k) + phi(k) / k, M1 = -Phi(k) / k, M2 = Phi(k) + 2 phi(k) / k.
// At grazing angles (small k) the visible facets lean towards the eye and spread less: the sky
// they reflect is higher above the horizon than the full Gaussian's (Bruneton 2010 Eq. 9 filters
// with the full distribution, the paper's largest error, its §7.2).
vec2 visibleSlopeMoments(Number k) {
  if (k > 6.0) return vec2(0.0, 1.0);
  Number kk = max(k, 1e-3);
  Number pdf = exp(-0.5 * kk * kk) / sqrt(2.0 * BRDF_PI);
  Number cdf = 1.0 - 0.5 * brdfErfc(kk / sqrt(2.0));
  Number m0 = cdf + pdf / kk;
  Number mean = -cdf / kk / m0;
  return vec2(mean, max((cdf + 2.0 * pdf / kk) / m0 - mean * mean, 0.0));
}
