// Procedural relief below the elevation layer's resolution: octaves of ridged 3-D gradient
// noise on the unit sphere (no seams at the antimeridian or the poles), amplitude falling as
// wavelength^H (gain 0.6 per octave: a self-affine surface of Hurst exponent H = -log2 0.6 =
// 0.737, in the range measured on real relief, H ≈ 0.7 (Gagnon, Lovejoy & Schertzer 2006,
// Nonlin. Processes Geophys. 13, 541), so RMS slopes grow as wavelength^(H-1) at finer scales
// as real ones do). The amplitude is calibrated on the CPU (terrain/Heightfield.cpp,
// detailShadingAmplitudeM; docs/terrain.md "Calibration of the detail"); the sea floor's
// detail (ocean/water_volume.glsl) uses the same weights.
//
// Compiled twice: as C++ in double (terrain/Heightfield.cpp: vertex heights and the normals
// the mesh resolves) and as GLSL in float (terrain.frag: the finer octaves' normals per pixel,
// as many as the pixel footprint allows). The caller supplies each octave's lattice cell and
// the position inside it, so the GPU never needs the absolute (large) lattice coordinates:
// the CPU splits the eye's coordinate per octave in double, the shader adds the offset.
// Needs Number, vec3, vec4, ivec3 and uint; GLSL-and-C++ subset only.

// Octave k has wavelength longest / 2^k; its lattice is the unit sphere scaled by
// (semi-major axis / wavelength) and shifted by detailOctaveOffset(k) so lattice points of
// different octaves do not line up.
// Weight of octave k before normalisation.
const Number DETAIL_GAIN = 0.6;
Number detailOctaveWeight(int k) { return pow(DETAIL_GAIN, Number(k)); }

vec3 detailOctaveOffset(int k) {
  Number o = 17.31 * Number(k + 1);
  return vec3(o, -o, 0.5 * o);
}

// Integer hash of a lattice point (murmur3's 32-bit finaliser over a mix of the coordinates):
// the same bits on the CPU and the GPU.
uint detailHash(ivec3 p) {
  uint h = uint(p.x) * 0x8DA6B343u + uint(p.y) * 0xD8163841u + uint(p.z) * 0xCB1AB31Fu;
  h ^= h >> 16u;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13u;
  h *= 0xC2B2AE35u;
  h ^= h >> 16u;
  return h;
}

// Gradient at a lattice point: one of the 12 cube-edge directions (Perlin's improved noise;
// 16 cases, 4 repeated, so a bit mask picks it).
// Written without branches (the CPU's tile builder mispredicted them at every lattice point):
// c < 8 puts su on x, else on y; c < 4 puts sv on y, c = 12 or 14 on x, else on z. Every
// term is 0 or ±1, so the sums are exact: the same vectors as the branches gave, but for the
// sign of some zeros (-0 for +0), which can only flip the sign of an exactly zero result.
vec3 detailGradient(uint h) {
  uint c = h & 15u;
  Number su = 1.0 - 2.0 * Number(c & 1u);
  Number sv = 1.0 - 2.0 * Number((c >> 1u) & 1u);
  Number low = Number(c < 8u), svOnY = Number(c < 4u), svOnX = Number(c == 12u || c == 14u);
  return vec3(low * su + svOnX * sv, (1.0 - low) * su + svOnY * sv, (1.0 - svOnY - svOnX) * sv);
}

// Gradient noise in about [-1, 1] at lattice cell `cell` and position `f` in [0,1)³ inside it,
// with its derivatives (lattice units): (value, d/dx, d/dy, d/dz). Quintic fade, C2-continuous.
vec4 detailNoise(ivec3 cell, vec3 f) {
  vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  vec3 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  vec3 ga = detailGradient(detailHash(cell));
  vec3 gb = detailGradient(detailHash(cell + ivec3(1, 0, 0)));
  vec3 gc = detailGradient(detailHash(cell + ivec3(0, 1, 0)));
  vec3 gd = detailGradient(detailHash(cell + ivec3(1, 1, 0)));
  vec3 ge = detailGradient(detailHash(cell + ivec3(0, 0, 1)));
  vec3 gf = detailGradient(detailHash(cell + ivec3(1, 0, 1)));
  vec3 gg = detailGradient(detailHash(cell + ivec3(0, 1, 1)));
  vec3 gh = detailGradient(detailHash(cell + ivec3(1, 1, 1)));
  Number va = dot(ga, f);
  Number vb = dot(gb, f - vec3(1.0, 0.0, 0.0));
  Number vc = dot(gc, f - vec3(0.0, 1.0, 0.0));
  Number vd = dot(gd, f - vec3(1.0, 1.0, 0.0));
  Number ve = dot(ge, f - vec3(0.0, 0.0, 1.0));
  Number vf = dot(gf, f - vec3(1.0, 0.0, 1.0));
  Number vg = dot(gg, f - vec3(0.0, 1.0, 1.0));
  Number vh = dot(gh, f - vec3(1.0, 1.0, 1.0));
  // Trilinear interpolation written as a polynomial in the fade weights, so the derivative is
  // the product rule over its terms.
  Number k1 = vb - va, k2 = vc - va, k3 = ve - va;
  Number k4 = va - vb - vc + vd, k5 = va - vc - ve + vg, k6 = va - vb - ve + vf;
  Number k7 = -va + vb + vc - vd + ve - vf - vg + vh;
  Number value = va + u.x * k1 + u.y * k2 + u.z * k3 + u.x * u.y * k4 + u.y * u.z * k5 +
                 u.z * u.x * k6 + u.x * u.y * u.z * k7;
  vec3 grad = ga + u.x * (gb - ga) + u.y * (gc - ga) + u.z * (ge - ga) +
              u.x * u.y * (ga - gb - gc + gd) + u.y * u.z * (ga - gc - ge + gg) +
              u.z * u.x * (ga - gb - ge + gf) + u.x * u.y * u.z * (-ga + gb + gc - gd + ge - gf - gg + gh);
  grad += du * vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z,
                    k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x,
                    k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
  return vec4(value, grad.x, grad.y, grad.z);
}

// One ridged octave: 1 - 2|n| has sharp crests and rounded valleys, like eroded relief; 0.45
// is its approximate mean, removed so the detail does not lift the terrain on average.
// For a pixel `cellsPerPixel` lattice cells wide, the crest's kink (where |n| turns and the
// gradient flips sign over no width) is rounded: |n| -> sqrt(n² + e²) - e with e the noise's
// change across a quarter pixel (the gradient turns over about half a pixel; over a whole one
// the Alps' contrast from 100 km drops by 10 % for no less shimmer). A point sample of the kink is the one part of a
// faded octave that is not band-limited: a sub-pixel shift of the sample (another triangle's
// interpolation at a shared edge with multisampling, a moving camera) would take the other
// side's normal (docs/terrain.md, "Multisampling and the detail").
// Returns (value, gradient in lattice units).
vec4 detailRidgedFiltered(ivec3 cell, vec3 f, Number cellsPerPixel) {
  vec4 n = detailNoise(cell, f);
  Number e = 0.25 * cellsPerPixel * length(vec3(n.y, n.z, n.w));
  Number a = sqrt(n.x * n.x + e * e);
  Number s = a > 0.0 ? 2.0 * n.x / a : 0.0;
  return vec4(1.0 - 2.0 * (a - e) - 0.45, -s * n.y, -s * n.z, -s * n.w);
}

// The kink point-sampled (e = 0): the heights' and the vertex normals' octaves, which the
// mesh resolves.
vec4 detailRidged(ivec3 cell, vec3 f) { return detailRidgedFiltered(cell, f, 0.0); }
