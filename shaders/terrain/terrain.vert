#version 450 core
// Terrain tiles: positions relative to the tile centre plus the tile centre relative to the
// camera (computed in double on the CPU), so nothing on the GPU is in world coordinates.
layout(location = 0) in vec3 aPosition;  // m, relative to the tile centre, ECEF axes
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aInfo;      // height m, latitude rad, longitude rad, detail amplitude m

uniform mat4 uViewProjection;  // for camera-relative ECEF positions
uniform vec3 uTileOffset;      // tile centre - eye, m

out vec3 vRelative;
out vec3 vNormal;
out vec4 vInfo;

void main() {
  vRelative = uTileOffset + aPosition;
  vNormal = aNormal;
  vInfo = aInfo;
  gl_Position = uViewProjection * vec4(vRelative, 1.0);
}
