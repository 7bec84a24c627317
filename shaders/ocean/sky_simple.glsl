// A simple analytic sky for the ocean's reflection until the precomputed sky maps are wired in:
// a zenith-to-horizon gradient in the stereographic parametrisation (ignores the gradients).
uniform vec3 uSkyZenith;   // radiance at the zenith
uniform vec3 uSkyHorizon;  // radiance at the horizon

vec3 oceanSkyMap(vec2 u, vec2 dudx, vec2 dudy) {
  float q = dot(u, u);
  float z = (1.0 - q) / (1.0 + q);  // inverse stereographic: cos(zenith angle)
  return mix(uSkyHorizon, uSkyZenith, sqrt(clamp(z, 0.0, 1.0)));
}
