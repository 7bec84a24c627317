// Stand-in surface materials until imagery layers exist: an albedo ramp by elevation, slope and
// latitude (sand at the shore, vegetation in the lowlands, rock on steep or high ground, snow
// above a snow line that falls towards the poles and slides off steep faces). Albedos are
// broadband-ish RGB reflectances of the named surfaces; nothing here is measured data.
vec3 terrainAlbedo(float heightM, float slope, float latitudeRad) {
  const vec3 sand = vec3(0.35, 0.30, 0.20);
  const vec3 wetSand = vec3(0.16, 0.14, 0.10);
  const vec3 grass = vec3(0.07, 0.12, 0.04);
  const vec3 dry = vec3(0.20, 0.17, 0.10);
  const vec3 rock = vec3(0.20, 0.18, 0.16);
  const vec3 snow = vec3(0.72, 0.74, 0.78);
  float lat = abs(latitudeRad);
  // Lowlands: vegetation, drier (browner) in the subtropical belt and at altitude.
  float aridity = smoothstep(0.25, 0.40, lat) * (1.0 - smoothstep(0.55, 0.70, lat));
  vec3 c = mix(grass, dry, clamp(0.6 * aridity + smoothstep(800.0, 2500.0, heightM), 0.0, 1.0));
  // Beaches just above the sea, wet sand / sea floor below it.
  c = mix(sand, c, smoothstep(2.0, 25.0, heightM));
  c = mix(wetSand, c, step(0.0, heightM));
  // Rock where steep, and above the tree line.
  float rocky = max(smoothstep(0.12, 0.30, slope), smoothstep(2500.0, 4000.0, heightM));
  c = mix(c, rock, rocky);
  // Snow: line at ~5500 m in the tropics, down to sea level near the poles; not on cliffs.
  float snowLine = mix(5500.0, 0.0, smoothstep(0.6, 1.2, lat));
  float snowy = smoothstep(snowLine - 300.0, snowLine + 300.0, heightM) * (1.0 - smoothstep(0.35, 0.55, slope));
  return mix(c, snow, snowy);
}
