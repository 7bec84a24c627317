// Stand-in surface materials until imagery layers exist: an albedo ramp by elevation, slope and
// latitude. Sand at the shore; vegetation in the lowlands (browner in the subtropical dry belt);
// above the tree line alpine grass and scree; rock on steep ground; snow above a snow line that
// falls from ~5600 m in the tropics to ~3000 m at 46° (the Alps) and sea level near 75°, and
// slides off steep faces. Albedos are broadband-ish RGB reflectances of the named surfaces;
// nothing here is measured data.
vec3 terrainAlbedo(float heightM, float slope, float latitudeRad) {
  const vec3 sand = vec3(0.35, 0.30, 0.20);
  const vec3 wetSand = vec3(0.16, 0.14, 0.10);
  const vec3 forest = vec3(0.05, 0.09, 0.035);
  const vec3 dry = vec3(0.22, 0.18, 0.11);
  const vec3 alpine = vec3(0.12, 0.13, 0.08);
  const vec3 rock = vec3(0.21, 0.20, 0.19);
  const vec3 snow = vec3(0.72, 0.74, 0.78);
  float latDeg = abs(latitudeRad) * (180.0 / PI);
  float snowLine = mix(5600.0, 0.0, smoothstep(20.0, 75.0, latDeg));
  float treeLine = snowLine - 1200.0;
  // Lowlands: forest, drier in the subtropical belt (deserts and steppes around 15-35°).
  float aridity = smoothstep(12.0, 22.0, latDeg) * (1.0 - smoothstep(32.0, 42.0, latDeg));
  vec3 c = mix(forest, dry, 0.7 * aridity);
  // Above the tree line: alpine grass and scree, greyer towards the snow line.
  c = mix(c, alpine, smoothstep(treeLine - 300.0, treeLine + 300.0, heightM));
  c = mix(c, rock, smoothstep(treeLine + 300.0, snowLine, heightM) * 0.7);
  // Beaches just above the sea, wet sand / sea floor below it.
  c = mix(sand, c, smoothstep(2.0, 25.0, heightM));
  c = mix(wetSand, c, step(0.0, heightM));
  // Bare rock where steep (cliffs, ridges, gullies).
  c = mix(c, rock, smoothstep(0.25, 0.45, slope));
  // Snow; not on cliffs.
  float snowy = smoothstep(snowLine - 250.0, snowLine + 250.0, heightM) * (1.0 - smoothstep(0.35, 0.55, slope));
  return mix(c, snow, snowy);
}

// The albedo where imagery covers the ground: the imagery's colour, with the procedural
// material's structure below the imagery's resolution keyed to it: rock on steep faces takes
// the imagery's brightness, snow stays above the snow line on gentle slopes (the imagery's
// ~20 km pixels blur alpine snow away); where the imagery shows water
// (its coarse pixels spill the sea onto land) the procedural material stands in.
vec3 terrainAlbedoOverImagery(vec3 imagery, vec3 procedural, float heightM, float slope, float latitudeRad) {
  float water = smoothstep(0.0, 0.04, imagery.b - max(imagery.r, imagery.g));
  vec3 c = mix(imagery, procedural, water);
  float luma = dot(c, vec3(0.2126, 0.7152, 0.0722));
  vec3 rock = vec3(1.05, 1.0, 0.93) * max(luma, 0.12);
  c = mix(c, rock, 0.6 * smoothstep(0.25, 0.45, slope));
  float latDeg = abs(latitudeRad) * (180.0 / PI);
  float snowLine = mix(5600.0, 0.0, smoothstep(20.0, 75.0, latDeg));
  float snowy = smoothstep(snowLine - 250.0, snowLine + 250.0, heightM) * (1.0 - smoothstep(0.35, 0.55, slope));
  return mix(c, vec3(0.72, 0.74, 0.78), 0.8 * snowy);
}
