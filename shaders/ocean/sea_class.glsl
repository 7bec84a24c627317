// A sea fragment's class (render/OceanRenderer's split; the classes are listed in
// ocean/sea_classify.frag) from the grid's per-vertex flags, and the record of each class's
// first and last grid row, shared by the classifying draw and the deferred sea's surface pass
// (ocean/sea_surface.frag).
#ifdef OCEAN_NO_WATER_VOLUME
const float vFloorDepthM = 1e4;  // no floor in reach (deeper than any reach: the water's d_max is ~150 m)
#else
in float vFloorDepthM;  // m below sea level under the pixel (ocean/water_volume_vertex.glsl)
#endif
in float vNearLand;     // > 0 where land may be within the triangle
in float vNearShadow;   // > 0 where the terrain's shadows may reach into the triangle
flat in int vGridRow;   // the triangle's grid row (its provoking vertex's, within one)

// Per class, the first and last grid row of its fragments (render/OceanRenderer reads them
// back and draws each class over those rows only, none where a class has no fragment). Read
// before the atomics: a fragment changes a bound only at a class's first and last rows.
layout(std430, binding = 3) buffer SeaClassRows { int seaClassRows[10]; };

uniform float uWaterReachM;  // the water volume's d_max (ocean::waterMaxPathM), m; -1: no volume
uniform int uCoastClass;     // 1: the frame's coast test is routed to class 5

// The fragment's class, 1-5, its grid row recorded.
int seaClassOfFragment() {
  // The water volume returns the deep sea's colour where the floor under the pixel (the same
  // interpolated vFloorDepthM) is deeper than d_max (ocean/water_volume.glsl): the same test.
  bool floor = vFloorDepthM <= uWaterReachM;
  int seaClass = floor ? 3 : 1;
  if (vNearShadow > 0.0) seaClass += 1;
  if (uCoastClass == 1 && vNearLand > 0.0) seaClass = 5;
  int k = 2 * (seaClass - 1);
  if (vGridRow < seaClassRows[k]) atomicMin(seaClassRows[k], vGridRow);
  if (vGridRow > seaClassRows[k + 1]) atomicMax(seaClassRows[k + 1], vGridRow);
  return seaClass;
}
