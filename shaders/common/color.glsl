// Display encoding: exposure, tone curve, sRGB transfer function (IEC 61966-2-1).

// Filmic-free exponential tone curve: linear near black, saturating smoothly; invertible.
vec3 toneMap(vec3 radiance, float exposure) {
  return vec3(1.0) - exp(-max(radiance, vec3(0.0)) * exposure);
}

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
