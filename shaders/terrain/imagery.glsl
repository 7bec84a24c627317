// Imagery draped as the land's albedo (render/ImageryTextures.hpp): the base day image (global,
// the embedded Blue Marble unless replaced), the user's `--imagery-layer`s over it (later ones on
// top, alpha = coverage), and the night lights. A user layer is sampled from its streamed tile
// for the terrain tile being drawn (render/ImageryTiles.hpp: uImageryTileSlot >= 0, set per
// draw) or else from its whole texture. All textures are sRGB-encoded, so samples are
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
// The user's layers a loop visits: none where the program is compiled without them
// (IMAGERY_NO_LAYERS: render/TerrainRenderer's variants, when none is loaded), since llvmpipe
// runs a loop's first trip, masked, even when no pixel enters it.
#ifdef IMAGERY_NO_LAYERS
#define IMAGERY_LAYER_COUNT 0
#else
#define IMAGERY_LAYER_COUNT min(uImageryLayerCount, MAX_IMAGERY_LAYERS)
#endif
uniform float uImageryLayerTexelRad;
uniform vec4 uImageryLayerBounds[MAX_IMAGERY_LAYERS];  // west, south, east, north, radians
// Streamed tiles (render/ImageryTiles), per draw and layer: the slot in uImageryTiles (-1: none,
// the whole layer texture), the bounds of the stored tile (west, south, east, north, radians:
// the tile and its border of data::kImageryTileBorderPx texels, the neighbours' edge texels, so
// filtering at the tile's edge blends into its neighbour) and its texel size.
layout(binding = OG_UNIT_IMAGERY_TILES) uniform sampler2DArray uImageryTiles;
uniform int uImageryTileSlot[MAX_IMAGERY_LAYERS];
uniform vec4 uImageryTileBounds[MAX_IMAGERY_LAYERS];
uniform float uImageryTileTexelRad[MAX_IMAGERY_LAYERS];
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

// Where (latitude, longitude) radians lies in the box b (west, south, east, north, radians):
// 0..1 inside, longitudes taken east of the box's west edge.
vec2 imageryBoxCoord(vec2 latLon, vec4 b) {
  float lon = b.x + mod(latLon.y - b.x, 2.0 * PI);
  return vec2((lon - b.x) / (b.z - b.x), (latLon.x - b.y) / (b.w - b.y));
}

// User layer i at (latitude, longitude): its streamed tile when one is bound, else its whole
// texture. Premultiplied by coverage (alpha).
vec4 imageryLayerSample(int i, vec2 latLon, vec2 st, float footprintRad, float lodWhole) {
  int slot = uImageryTileSlot[i];
  if (slot < 0) return textureLod(uImageryLayers, vec3(st, float(i)), lodWhole);
  vec2 tileSt = imageryBoxCoord(latLon, uImageryTileBounds[i]);
  return textureLod(uImageryTiles, vec3(tileSt, float(slot)), imageryLod(footprintRad, uImageryTileTexelRad[i]));
}

// Day colour (linear albedo) at (latitude, longitude) radians for a footprint in radians of arc.
// The layers are composited top down ("under"): acc gathers the colour seen so far, through the
// transmittance T = Π (1 - alpha) of the layers above; where a layer covers fully (T ~ 0) the
// ones below and the base image are not sampled at all. The same sum as bottom-up "over".
vec3 imageryAlbedo(vec2 latLon, float footprintRad) {
  vec3 acc = vec3(0.0);
  float T = 1.0;
  float lodLayers = imageryLod(footprintRad, uImageryLayerTexelRad);
  for (int i = IMAGERY_LAYER_COUNT - 1; i >= 0 && T > 0.5 / 255.0; --i) {
    vec2 st = imageryBoxCoord(latLon, uImageryLayerBounds[i]);
    if (st.x < 0.0 || st.x > 1.0 || st.y < 0.0 || st.y > 1.0) continue;
    // No-data texels are black with alpha 0, so mip-mapped colour is premultiplied by coverage.
    vec4 l = imageryLayerSample(i, latLon, st, footprintRad, lodLayers);
    acc += T * l.rgb;
    T *= 1.0 - l.a;
  }
  if (T > 0.5 / 255.0) {
    vec2 uv = vec2(fract(latLon.y / (2.0 * PI) + 0.5), latLon.x / PI + 0.5);
    acc += T * textureLod(uImageryDay, uv, imageryLod(footprintRad, uImageryDayTexelRad)).rgb;
  }
  return IMAGERY_ALBEDO_SCALE * pow(max(acc, vec3(0.0)), vec3(IMAGERY_ALBEDO_POWER));
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
