// The clear sea's radiance (ocean/lighting.glsl's seaRadianceAt: glint, sky, refracted) as a
// quadratic in what varies from pixel to pixel, computed at the projected grid's vertices where
// its cells are large (render/OceanRenderer, OCEAN_RADIANCE_TERMS; docs/ocean.md, "The radiance
// at the vertices").
//
// Why it holds: where the grid's cells grow (the waves' geometry sub-pixel, no horizon), a
// pixel's radiance depends on the eye, the Sun and the point's vertical, all smooth over a cell,
// and on the pixel's own sea: the mean slope its footprint resolves, s (frame axes), and the
// slope covariance it leaves to the BRDF, c = (xx, yy, xy) in the local wind's frame (Bruneton
// 2010 Eqs. 3-4). Those two vary from pixel to pixel by a fraction of the BRDF's own width (the
// unresolved slopes' standard deviation), so the radiance is close to a quadratic in them
// around the cell's values: the vertex evaluates it 13 times (at the expansion point, a step
// either side in each of the five variables, and two diagonal steps for the slopes' cross
// term), the triangle interpolates the quadratic's coefficients, and the pixel evaluates the
// quadratic at its own s and c.
//
// Written in the twins' subset (common/types.glsl): src/ocean/Lighting.cpp compiles this file as
// C++ (ocean::lighting::seaRadianceTerms, its tests).

// Coefficients per colour channel of R(x) = k[0] + sum_d (k[1 + d] x_d + k[6 + d] x_d²)
// + k[11] s.x s.y over x = (s.x, s.y, c.x, c.y, c.z): the slopes' cross term (the glint's lobe
// is a Gaussian in both), none between the other variables.
const int SEA_RADIANCE_TERMS = 12;
struct SeaRadianceTerms {
  vec3 k[SEA_RADIANCE_TERMS];
};

// The mean normal (ECEF, unit) of a footprint whose resolved mean slope is `slope` (dz/dx,
// dz/dy in the ocean frame's axes, whose axes are the rows of oceanToEcef's transpose), at a
// point of vertical upE: the waves live in the frame's tangent plane, their normal tilted onto
// the ellipsoid's curvature so that with the waves faded out it is exactly the ellipsoid's (as
// in orbit).
vec3 seaTiltedNormal(vec2 slope, mat3 oceanToEcef, vec3 upE) {
  vec3 frameUp = oceanToEcef[2];
  vec3 nFrame = oceanToEcef * normalize(vec3(-slope.x, -slope.y, 1.0));
  return normalize(nFrame + (upE - frameUp) * dot(nFrame, frameUp));
}
// A normal facing away from the eye (vE: unit, to the eye), as seen at grazing angles,
// reflected about the view plane (§5.1).
vec3 seaNormalFacing(vec3 n, vec3 vE) {
  Number nv = dot(n, vE);
  return nv < 0.0 ? normalize(n - 2.0 * nv * vE) : n;
}
vec3 seaNormalOfSlope(vec2 slope, mat3 oceanToEcef, vec3 upE, vec3 vE) {
  return seaNormalFacing(seaTiltedNormal(slope, oceanToEcef, upE), vE);
}

// A place on the sea, what its radiance needs whatever the footprint's slopes: the view, the
// Sun and the light arriving (seaPoint's work but the normal), the wind in its local frame, and
// what turns a slope into a normal.
struct SeaPlace {
  SeaPoint p;
  mat3 toLocal;  // ECEF to the local frame
  vec3 windLocal;
  mat3 oceanToEcef;
  vec3 upE, vE;
};
SeaPlace seaPlace(vec3 vE, mat3 oceanToEcef, vec3 windE, vec3 upE, vec3 sunE) {
  SeaPlace place;
  place.p = seaPoint(vE, upE, windE, upE, sunE);
  place.toLocal = transpose(localFrame(upE));
  place.windLocal = place.toLocal * windE;
  place.oceanToEcef = oceanToEcef;
  place.upE = upE;
  place.vE = vE;
  return place;
}

// The clear sea's radiance (no foam) at `place` for a footprint of mean slope `slope` and
// unresolved slope covariance `cov` (as above): ocean/lighting.glsl's seaRadiance.
vec3 clearSeaRadiance(SeaPlace place, vec2 slope, vec3 cov) {
  SeaPoint p = place.p;
  setSeaNormal(p, place.toLocal * seaNormalOfSlope(slope, place.oceanToEcef, place.upE, place.vE), place.windLocal);
  return seaRadianceAt(p, cov, place.upE);
}

// Variable d's terms from the radiance at its expansion value e (r0) and a step h either side
// (rPlus, rMinus): the central differences' slope j and half second derivative q give
// r0 + j (x - e) + q (x - e)², stored by powers of x.
void addSeaRadianceTerm(INOUT(SeaRadianceTerms) t, int d, Number e, Number h, vec3 r0, vec3 rPlus, vec3 rMinus) {
  vec3 j = (rPlus - rMinus) / (2.0 * h);
  vec3 q = (rPlus + rMinus - 2.0 * r0) / (2.0 * h * h);
  t.k[0] += q * (e * e) - j * e;
  t.k[1 + d] = j - q * (2.0 * e);
  t.k[6 + d] = q;
}

// The quadratic around the cell's mean slope `slope` and a pixel's covariance there `cov`, with
// steps of `slopeStep` (the spread of the pixels' mean slopes about it, > 0) and a tenth of each
// variance and of the cross term's room (below): 13 radiances.
SeaRadianceTerms seaRadianceTerms(SeaPlace place, vec2 slope, vec3 cov, Number slopeStep) {
  SeaRadianceTerms t;
  vec3 r0 = clearSeaRadiance(place, slope, cov);
  t.k[0] = r0;
  vec2 hx = vec2(slopeStep, 0.0), hy = vec2(0.0, slopeStep);
  vec3 rxp = clearSeaRadiance(place, slope + hx, cov);
  vec3 rxm = clearSeaRadiance(place, slope - hx, cov);
  vec3 ryp = clearSeaRadiance(place, slope + hy, cov);
  vec3 rym = clearSeaRadiance(place, slope - hy, cov);
  addSeaRadianceTerm(t, 0, slope.x, slopeStep, r0, rxp, rxm);
  addSeaRadianceTerm(t, 1, slope.y, slopeStep, r0, ryp, rym);
  // The cross term m (x - ex)(y - ey), m from the diagonal steps (exact for a quadratic).
  vec3 rpp = clearSeaRadiance(place, slope + hx + hy, cov);
  vec3 rmm = clearSeaRadiance(place, slope - hx - hy, cov);
  vec3 m = (rpp + rmm - rxp - rxm - ryp - rym + 2.0 * r0) / (2.0 * slopeStep * slopeStep);
  t.k[0] += m * (slope.x * slope.y);
  t.k[1] -= m * slope.y;
  t.k[2] -= m * slope.x;
  t.k[11] = m;
  // Steps that keep the covariance a covariance: a tenth of each variance, and of the cross
  // term's room, sqrt(xx yy - xy²).
  vec2 var = max(vec2(cov.x, cov.y), vec2(1e-7));
  vec3 hc = 0.1 * vec3(var.x, var.y, sqrt(max(var.x * var.y - cov.z * cov.z, 1e-14)));
  vec3 cx = vec3(hc.x, 0.0, 0.0), cy = vec3(0.0, hc.y, 0.0), cxy = vec3(0.0, 0.0, hc.z);
  addSeaRadianceTerm(t, 2, cov.x, hc.x, r0, clearSeaRadiance(place, slope, cov + cx),
                     clearSeaRadiance(place, slope, cov - cx));
  addSeaRadianceTerm(t, 3, cov.y, hc.y, r0, clearSeaRadiance(place, slope, cov + cy),
                     clearSeaRadiance(place, slope, cov - cy));
  addSeaRadianceTerm(t, 4, cov.z, hc.z, r0, clearSeaRadiance(place, slope, cov + cxy),
                     clearSeaRadiance(place, slope, cov - cxy));
  return t;
}

// The quadratic's value at a pixel's mean slope and covariance (never below 0: far past its
// steps a quadratic about the glint's peak turns negative).
vec3 seaRadianceOfTerms(SeaRadianceTerms t, vec2 slope, vec3 cov) {
  return max(t.k[0] + (t.k[1] + t.k[6] * slope.x) * slope.x + (t.k[2] + t.k[7] * slope.y) * slope.y +
                 (t.k[3] + t.k[8] * cov.x) * cov.x + (t.k[4] + t.k[9] * cov.y) * cov.y +
                 (t.k[5] + t.k[10] * cov.z) * cov.z + t.k[11] * (slope.x * slope.y),
             vec3(0.0));
}

// The aerial perspective folded into the terms and the foam's radiance: each times the path's
// transmittance, the light scattered in added to the constant and to the foam, so that
// mixFoam(seaRadianceOfTerms(t, s, c), foam, W) is the per-pixel mixFoam(R, F, W) T + I.
void foldAerialPerspective(INOUT(SeaRadianceTerms) t, INOUT(vec3) foam, vec3 transmittance, vec3 inscatter) {
  for (int i = 0; i < SEA_RADIANCE_TERMS; ++i) t.k[i] = t.k[i] * transmittance;
  t.k[0] = t.k[0] + inscatter;
  foam = foam * transmittance + inscatter;
}

#ifndef OG_GLSL_SHIM
// The terms and the foam's radiance as the grid's vertices hand them to the pixels: 13 vec3
// packed into 10 vec4 (varyings count in vec4 slots on some drivers).
const int SEA_RADIANCE_VEC4S = 10;
// Four vec3 into three vec4 at slots[3 g], and back.
void packFour(int g, vec3 a, vec3 b, vec3 c, vec3 d, inout vec4 slots[SEA_RADIANCE_VEC4S]) {
  slots[3 * g] = vec4(a, b.x);
  slots[3 * g + 1] = vec4(b.yz, c.xy);
  slots[3 * g + 2] = vec4(c.z, d);
}
vec3 unpackOne(int g, int i, vec4 slots[SEA_RADIANCE_VEC4S]) {
  vec4 p0 = slots[3 * g], p1 = slots[3 * g + 1], p2 = slots[3 * g + 2];
  return i == 0 ? p0.xyz : i == 1 ? vec3(p0.w, p1.xy) : i == 2 ? vec3(p1.zw, p2.x) : p2.yzw;
}
void packSeaRadianceTerms(SeaRadianceTerms t, vec3 foam, inout vec4 slots[SEA_RADIANCE_VEC4S]) {
  packFour(0, t.k[0], t.k[1], t.k[2], t.k[3], slots);
  packFour(1, t.k[4], t.k[5], t.k[6], t.k[7], slots);
  packFour(2, t.k[8], t.k[9], t.k[10], t.k[11], slots);
  slots[9] = vec4(foam, 0.0);
}
SeaRadianceTerms unpackSeaRadianceTerms(vec4 slots[SEA_RADIANCE_VEC4S]) {
  SeaRadianceTerms t;
  for (int i = 0; i < SEA_RADIANCE_TERMS; ++i) t.k[i] = unpackOne(i / 4, i % 4, slots);
  return t;
}
vec3 unpackFoamRadiance(vec4 slots[SEA_RADIANCE_VEC4S]) { return slots[9].xyz; }
#endif
