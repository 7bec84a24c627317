#pragma once
// Uniforms of the water volume (shaders/ocean/water_optics.glsl, water_volume.glsl,
// terrain/shallow.glsl): the water type's attenuation, the sea floor's albedo, and the floor
// detail's noise lattice at the eye.
#include <limits>
#include <string>
#include <vector>

#include "data/LatLonGrid.hpp"
#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "gl/ShaderContract.hpp"
#include "ocean/WaterOptics.hpp"
#include "render/OceanPatterns.hpp"

namespace og::render {

/// The longest wavelength of the floor's detail octaves (water_volume.glsl), m; each next
/// octave halves it (8, 4, ... 0.25 m).
inline constexpr double kFloorDetailLongestM = 8.0;
inline constexpr int kFloorDetailOctaves = 6;  ///< FLOOR_OCTAVES

/// The water's optics for the globe's and the grid's sea: its attenuation and the floor albedo.
void setWaterOptics(const gl::Program& p, const ocean::WaterType& water);

/// The floor detail's lattice at the eye (for the grid's sea): each octave's lattice coordinate
/// split in double into a cell and a position in it, as the terrain does for its detail.
void setFloorDetail(const gl::Program& p, const geo::CameraView& view);

/// The steepest slope of `layer`'s bilinear surface (m of height per m along the ellipsoid of
/// the semi-major axis), over every pair of neighbouring cells, missing values read as -1 m as
/// the elevation texture has them. Bounds how far land can lie from a point by its height (the
/// sea's classes: shaders/ocean/water_volume_vertex.glsl's prepareSeaClassVertex, without the
/// land mask; a regional layer's border, where the -1 m outside meets it, is handled there).
double layerMaxSlope(const data::LatLonGrid& layer);

/// How many of the finest wave patterns focus the Sun onto the floor (water_volume.glsl's
/// caustics): the ones whose curvature matters at a few metres (longer waves focus far deeper).
inline constexpr int kCausticPatterns = 2;
/// The texture unit of the caustics' curvature map (water_volume.glsl's uCausticCurvature).
inline constexpr unsigned kCausticCurvatureUnit = gl::kUnitCausticCurvature;

/// The defines of programs including shaders/ocean/water_volume.glsl (CAUSTIC_PATTERNS).
std::vector<std::string> waterVolumeDefines();

/// The caustics' curvature map (shaders/ocean/caustic_curvature.comp): the trace of the
/// finest wave patterns' height Hessian per texel, mip-mapped, refreshed when the patterns
/// change; sampled by the grid's water volume (one lookup per pattern and wind bin instead of
/// the finite differences of three filtered slopes).
class CausticCurvature {
 public:
  /// Needs a current GL 4.5 context.
  CausticCurvature();
  /// Recomputes the map from `patterns` (which hold the sea at `timeS`) unless it already
  /// holds that time of those patterns.
  void update(const OceanPatterns& patterns, double timeS);
  /// Binds the map to kCausticCurvatureUnit.
  void bind() const;

 private:
  gl::Program program_;
  gl::Texture texture_;
  int size_ = 0;
  GLuint source_ = 0;
  double timeS_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace og::render
