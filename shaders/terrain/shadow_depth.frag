#version 450 core
// The Sun's shadow map: depth only (terrain.vert with the light's matrix). Ground below sea
// level casts no shadow: it lies under the water surface, which it must not shade.
in vec4 vInfo;  // height m, latitude, longitude, detail amplitude
void main() {
  if (vInfo.x < 0.0) discard;
}
