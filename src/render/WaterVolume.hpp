#pragma once
// Uniforms of the water volume (shaders/ocean/water_optics.glsl, water_volume.glsl,
// terrain/shallow.glsl): the water type's attenuation, the sea floor's albedo, and the floor
// detail's noise lattice at the eye.
#include "geo/Camera.hpp"
#include "gl/Shader.hpp"
#include "ocean/WaterOptics.hpp"

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

}  // namespace og::render
