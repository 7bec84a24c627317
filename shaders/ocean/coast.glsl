// Where the sea is: the elevation layer decides (at or below 0 m). Both sea shaders test each
// of the pixel's samples (interpolateAtSample, no per-sample shading) and keep only the sea's
// in gl_SampleMask, so under multisampling the shoreline's land side is anti-aliased too.
#include "geo/ellipsoid.glsl"
#include "render/elevation.glsl"

// Whether the point at camera-relative `relative` (on or near the ellipsoid) is over the sea.
bool seaAt(vec3 relative) {
  if (uElevationSize.x <= 0.0) return true;
  float d = length(relative);
  return elevationAt(latLonOfNormal(ellipsoidNormal(relative / d, d))) <= 0.0;
}
