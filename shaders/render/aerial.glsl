// Aerial perspective between the eye and a point of the globe's surface (or the sea), with the
// geometry convention of render/globe.frag: the tables' sphere of radius R = bottomRadius, the
// eye at R + uCamAltitude, the path length t kept exact and its zenith cosine chosen so that
// the path joins the eye's altitude to altitude 0 (see globe.frag's header).
#include "atmosphere/model.glsl"

uniform vec3 uCamUp;        // geodetic normal under the camera, ECEF axes
uniform float uCamAltitude; // camera height above the ellipsoid, m

// surface: radiance leaving the point towards the eye; dir: unit view ray (ECEF axes);
// t: distance to the point, m; sunDir: unit, towards the Sun.
vec3 withAerialPerspective(vec3 surface, vec3 dir, float t, vec3 sunDir) {
  float R = uAtmosphere.bottomRadius;
  float h = uCamAltitude;
  float r = R + h;
  float rho2 = h * (2.0 * R + h);
  float d = min(t, sqrt(rho2));
  float mu = -(rho2 + d * d) / (2.0 * r * max(d, 1e-3));
  vec3 transmittance;
  vec3 inscatter = skyRadianceToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering,
                                      uAtmSingleMie, r, mu, dot(sunDir, uCamUp),
                                      dot(dir, sunDir), d, transmittance);
  return surface * transmittance + inscatter;
}
