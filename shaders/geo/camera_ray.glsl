// The camera's rays (geo::CameraView::rayDirection): its basis and the tangents of half its
// field of view, set by the passes that cast rays through the view (render/GlobeRenderer,
// render/OceanRenderer).
uniform vec3 uRight;       // camera basis, ECEF axes
uniform vec3 uUp;
uniform vec3 uForward;
uniform vec2 uTanHalfFov;  // (tan(fov_y/2) * aspect, tan(fov_y/2))

// The unit ray through the normalised device position `ndc`, ECEF axes.
vec3 cameraRay(vec2 ndc) { return normalize(uForward + ndc.x * uTanHalfFov.x * uRight + ndc.y * uTanHalfFov.y * uUp); }
