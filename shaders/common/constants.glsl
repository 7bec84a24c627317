// Shared numeric constants (mirrors src/geo/Wgs84.hpp).
const float PI = 3.14159265358979;
const float WGS84_A = 6378137.0;          // semi-major axis, m
const float WGS84_B = 6356752.314245179;  // semi-minor axis, m

// atan(y, x) is undefined at (0, 0) in GLSL (llvmpipe returns NaN): directions straight up,
// points exactly at a pole and calm winds all land there. Any angle will do at that point.
float atan2Safe(float y, float x) { return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x); }
