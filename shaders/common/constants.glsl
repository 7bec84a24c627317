// Shared numeric constants (mirrors src/geo/Wgs84.hpp).
const float PI = 3.14159265358979;
const float WGS84_A = 6378137.0;          // semi-major axis, m
const float WGS84_B = 6356752.314245179;  // semi-minor axis, m
