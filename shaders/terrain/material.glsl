// Stand-in surface materials until imagery layers exist: an albedo ramp by elevation, slope and
// latitude. Sand at the shore; vegetation in the lowlands (browner in the subtropical dry belt);
// above the tree line alpine grass and scree; rock on steep ground; snow above the snow line
// (terrainSnowLineM) that slides off steep faces. Albedos are broadband-ish RGB reflectances of
// the named surfaces; nothing here is measured data.

// The climatic snow line, m above sea level, at |latitude| latitudeDeg: highest not at the
// equator (~4800 m) but in the dry subtropics and the continental interiors around 30-35°
// (~5900 m: Tibet's interior, where the plateau at 4500-5200 m is brown, not white; the
// Andes' Puna), then falling fast to ~3000 m at 46° (the Alps), ~1200 m at 62° (Norway) and
// sea level near 76°. Piecewise linear through those reference heights, the textbook shape of
// the snow line against latitude (e.g. Flint 1971, "Glacial and Quaternary Geology"); one
// curve for both hemispheres, a stand-in, not a climatology.
float terrainSnowLineM(float latitudeDeg) {
  const int N = 11;
  const float lat[N] = float[N](0.0, 20.0, 28.0, 33.0, 37.0, 42.0, 46.0, 55.0, 62.0, 70.0, 76.0);
  const float line[N] = float[N](4800.0, 5200.0, 5600.0, 5900.0, 5600.0, 4000.0, 3000.0, 2000.0, 1200.0, 400.0, 0.0);
  float a = abs(latitudeDeg);
  for (int i = 1; i < N; ++i)
    if (a < lat[i]) return mix(line[i - 1], line[i], (a - lat[i - 1]) / (lat[i] - lat[i - 1]));
  return 0.0;
}
// A beach's width, m: the sand band covers this much of a pixel's footprint on the coast.
const float TERRAIN_BEACH_WIDTH_M = 100.0;

// snowLineM: terrainSnowLineM at the point's latitude (the caller's, shared with
// terrainAlbedoOverImagery: its loop is a tenth of the terrain's pixel from orbit on llvmpipe).
// footprintM: the pixel's footprint on the ground, m: where it is wider than a beach, the
// sand takes only the beach's share of it (from orbit a coast pixel spans kilometres: all
// sand, it sparkled along every coastline).
vec3 terrainAlbedo(float heightM, float slope, float latitudeRad, float snowLineM, float footprintM) {
  const vec3 sand = vec3(0.35, 0.30, 0.20);
  const vec3 wetSand = vec3(0.16, 0.14, 0.10);
  const vec3 forest = vec3(0.05, 0.09, 0.035);
  const vec3 dry = vec3(0.22, 0.18, 0.11);
  const vec3 alpine = vec3(0.12, 0.13, 0.08);
  const vec3 rock = vec3(0.21, 0.20, 0.19);
  const vec3 snow = vec3(0.72, 0.74, 0.78);
  float latDeg = abs(latitudeRad) * (180.0 / PI);
  float treeLine = snowLineM - 1200.0;
  // Lowlands: forest, drier in the subtropical belt (deserts and steppes around 15-35°).
  float aridity = smoothstep(12.0, 22.0, latDeg) * (1.0 - smoothstep(32.0, 42.0, latDeg));
  vec3 c = mix(forest, dry, 0.7 * aridity);
  // Above the tree line: alpine grass and scree, greyer towards the snow line.
  c = mix(c, alpine, smoothstep(treeLine - 300.0, treeLine + 300.0, heightM));
  c = mix(c, rock, smoothstep(treeLine + 300.0, snowLineM, heightM) * 0.7);
  // Beaches just above the sea, wet sand / sea floor below it.
  float beachShare = min(TERRAIN_BEACH_WIDTH_M / max(footprintM, 1e-3), 1.0);
  c = mix(c, sand, beachShare * (1.0 - smoothstep(2.0, 25.0, heightM)));
  c = mix(wetSand, c, step(0.0, heightM));
  // Bare rock where steep (cliffs, ridges, gullies).
  c = mix(c, rock, smoothstep(0.25, 0.45, slope));
  // Snow; not on cliffs.
  float snowy = smoothstep(snowLineM - 250.0, snowLineM + 250.0, heightM) * (1.0 - smoothstep(0.35, 0.55, slope));
  return mix(c, snow, snowy);
}

// The albedo where imagery covers the ground: the imagery's colour, with the procedural
// material's structure below the imagery's resolution keyed to it: rock on steep faces takes
// the imagery's brightness, snow above the snow line on gentle slopes where the pixel is finer
// than the imagery (its ~20 km pixels blur alpine snow away); where the pixel is as coarse as
// the imagery's texel or coarser, the imagery decides: no snow where it is brown (Tibet's dry
// plateau), snow where it is white (ice sheets, snowy ranges in winter imagery). `pixelPerTexel`: the pixel's footprint over the
// imagery's texel there, both angles. Where the imagery shows water (its coarse pixels spill
// the sea onto land) the procedural material stands in. snowLineM: as terrainAlbedo's.
vec3 terrainAlbedoOverImagery(vec3 imagery, vec3 procedural, float heightM, float slope, float snowLineM,
                              float pixelPerTexel) {
  float water = smoothstep(0.0, 0.04, imagery.b - max(imagery.r, imagery.g));
  vec3 c = mix(imagery, procedural, water);
  float luma = dot(c, vec3(0.2126, 0.7152, 0.0722));
  vec3 rock = vec3(1.05, 1.0, 0.93) * max(luma, 0.12);
  c = mix(c, rock, 0.6 * smoothstep(0.25, 0.45, slope));
  float snowy = smoothstep(snowLineM - 250.0, snowLineM + 250.0, heightM) * (1.0 - smoothstep(0.35, 0.55, slope));
  // At coarse scale only where the imagery itself shows snow: bright in every channel and
  // nearly grey (Blue Marble's ice sheets and snowy ranges reach ~0.5 in albedo after
  // imagery.glsl's scaling; deserts ~0.44 red but ~0.25 blue). Fully procedural from 4 pixels
  // per texel, fully the imagery's from 1.
  float fine = 1.0 - smoothstep(0.25, 1.0, pixelPerTexel);
  float lo = min(min(imagery.r, imagery.g), imagery.b), hi = max(max(imagery.r, imagery.g), imagery.b);
  float imagerySnow = smoothstep(0.25, 0.35, lo) * smoothstep(0.8, 0.9, lo / max(hi, 1e-4));
  snowy *= mix(imagerySnow, 1.0, fine);
  return mix(c, vec3(0.72, 0.74, 0.78), 0.8 * snowy);
}
