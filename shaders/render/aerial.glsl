// Aerial perspective between the eye and a point of the globe's surface (or the sea), with the
// geometry convention of render/globe.frag: the tables' sphere of radius R = bottomRadius, the
// eye at R + uCamAltitude, the path length t kept exact and its zenith cosine chosen so that
// the path joins the eye's altitude to altitude 0 (see globe.frag's header).
#include "atmosphere/model.glsl"

uniform vec3 uCamUp;        // geodetic normal under the camera, ECEF axes
uniform float uCamAltitude; // camera height above the ellipsoid, m

// The light of the path from the eye to a point of the surface: dir, unit view ray (ECEF axes);
// t: distance to the point, m; sunDir: unit, towards the Sun. What the point sends towards the
// eye arrives as surface * transmittance + inscatter.
void aerialPerspective(vec3 dir, float t, vec3 sunDir, out vec3 transmittance, out vec3 inscatter) {
  float R = uAtmosphere.bottomRadius;
  float h = uCamAltitude;
  float r = R + h;
  float rho2 = h * (2.0 * R + h);
  float d = min(t, sqrt(rho2));
  float mu = -(rho2 + d * d) / (2.0 * r * max(d, 1e-3));
  inscatter = skyRadianceToPoint(uAtmosphere, uAtmTransmittance, uAtmScattering, uAtmSingleMie, r,
                                 mu, dot(sunDir, uCamUp), dot(dir, sunDir), d, transmittance);
}

// surface: radiance leaving the point towards the eye; the rest as aerialPerspective.
vec3 withAerialPerspective(vec3 surface, vec3 dir, float t, vec3 sunDir) {
  vec3 transmittance, inscatter;
  aerialPerspective(dir, t, sunDir, transmittance, inscatter);
  return surface * transmittance + inscatter;
}
