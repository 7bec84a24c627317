// Imagery draped as the land's albedo (render/ImageryTextures.hpp): the base day image (global,
// the embedded Blue Marble unless replaced), the user's `--imagery-layer`s over it (later ones on
// top, alpha = coverage), and the night lights. All textures are sRGB-encoded, so samples are
// linear. Mip levels come from the pixel's footprint on the ground (an angle, radians of arc),
// not from derivatives: the globe pass shades several samples per pixel in a loop, and longitude
// jumps by 2 pi across the antimeridian.
// Needs common/constants.glsl.
layout(binding = OG_UNIT_IMAGERY_DAY) uniform sampler2D uImageryDay;        // rgb day colour, rows south to north
layout(binding = OG_UNIT_IMAGERY_NIGHT) uniform sampler2D uImageryNight;      // rgb night lights
layout(binding = OG_UNIT_IMAGERY_LAYERS) uniform sampler2DArray uImageryLayers; // the user's layers, rgba
const int MAX_IMAGERY_LAYERS = 8;  // data::kMaxImageryLayers
uniform int uImageryEnabled;        // 0: the stand-in material ramps (no imagery)
uniform float uImageryDayTexelRad;  // angular size of a base texel, radians
uniform int uImageryLayerCount;
uniform float uImageryLayerTexelRad;
uniform vec4 uImageryLayerBounds[MAX_IMAGERY_LAYERS];  // west, south, east, north, radians
uniform float uNightLights;         // scale of the night lights, 1 by default, 0 = off

// Blue Marble is a true-colour composite stretched for display: decoded from sRGB, its desert
// is ~0.7 in linear red and its rain forest ~0.045 in green, where measured reflectances are
// ~0.35-0.45 for the Sahara (Tsvetsinskaya et al. 2002) and ~0.05-0.08 in green for tropical
// forest. albedo = IMAGERY_ALBEDO_SCALE * linear^IMAGERY_ALBEDO_POWER undoes the stretch to
// first order: desert red 0.44, forest green 0.05.
const float IMAGERY_ALBEDO_SCALE = 0.5;
const float IMAGERY_ALBEDO_POWER = 0.6;

// Radiance of a fully lit night-image pixel, in units of the Sun's irradiance: a display scale,
// not a measurement (real city lights are ~1e-5 of daylight and would be black at the daylight
// exposure), chosen so lights read clearly at the default exposure without saturating.
const float NIGHT_LIGHTS_RADIANCE = 0.04;

float imageryLod(float footprintRad, float texelRad) {
  return log2(max(footprintRad / texelRad, 1.0));
}

// Day colour (linear albedo) at (latitude, longitude) radians for a footprint in radians of arc.
// a = how much of it is real imagery (1 everywhere with the global base image).
vec3 imageryAlbedo(vec2 latLon, float footprintRad) {
  vec2 uv = vec2(fract(latLon.y / (2.0 * PI) + 0.5), latLon.x / PI + 0.5);
  vec3 c = textureLod(uImageryDay, uv, imageryLod(footprintRad, uImageryDayTexelRad)).rgb;
  float lodLayers = imageryLod(footprintRad, uImageryLayerTexelRad);
  for (int i = 0; i < min(uImageryLayerCount, MAX_IMAGERY_LAYERS); ++i) {
    vec4 b = uImageryLayerBounds[i];
    float lon = b.x + mod(latLon.y - b.x, 2.0 * PI);  // east of the layer's west edge
    vec2 st = vec2((lon - b.x) / (b.z - b.x), (latLon.x - b.y) / (b.w - b.y));
    if (st.x < 0.0 || st.x > 1.0 || st.y < 0.0 || st.y > 1.0) continue;
    // No-data texels are black with alpha 0, so mip-mapped colour is premultiplied by coverage.
    vec4 l = textureLod(uImageryLayers, vec3(st, float(i)), lodLayers);
    c = c * (1.0 - l.a) + l.rgb;
  }
  return IMAGERY_ALBEDO_SCALE * pow(max(c, vec3(0.0)), vec3(IMAGERY_ALBEDO_POWER));
}

// How much an imagery colour looks like open water (Blue Marble's sea, lakes and the coastal
// strip that its ~20 km pixels blur onto the shore): 0 for land colours, 1 for deep blue.
float imageryWaterness(vec3 albedo) {
  return smoothstep(0.0, 0.04, albedo.b - max(albedo.r, albedo.g));
}

// Night lights (radiance) for a point whose Sun is muS (cosine of its zenith angle) above the
// horizon: none in daylight, fading in through twilight (Sun 0° to 6° below the horizon).
vec3 nightLightsRadiance(vec2 latLon, float footprintRad, float muS) {
  float dark = 1.0 - smoothstep(-0.105, 0.0, muS);
  if (dark <= 0.0 || uNightLights <= 0.0 || uImageryEnabled == 0) return vec3(0.0);
  vec2 uv = vec2(fract(latLon.y / (2.0 * PI) + 0.5), latLon.x / PI + 0.5);
  vec3 lights = textureLod(uImageryNight, uv, imageryLod(footprintRad, uImageryDayTexelRad)).rgb;
  return dark * uNightLights * NIGHT_LIGHTS_RADIANCE * lights;
}
