#pragma once
// This frame's aerial perspective tables (render/aerial.glsl, render/aerial_table.comp): for a
// fixed eye and Sun the light of the path from the eye to a point depends on a few numbers only,
// so a compute pass tabulates it once per frame and the passes read three filtered lookups
// instead of ten into the atmosphere's 4D tables per pixel or vertex.
#include <glm/glm.hpp>

#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "render/Atmosphere.hpp"

namespace og::render {

class AerialTable {
 public:
  enum class Kind {
    /// Paths to sea level (AERIAL_TABLE; the globe's parts above the grid's ceiling): ν × d,
    /// three layers of an RGBA32F array on gl::kUnitAerialTable.
    seaLevel,
    /// Paths to altitudes (TERRAIN_AERIAL_TABLE; the terrain's vertices): ν × d × altitude,
    /// one RGBA32F 3D texture of three blocks along x on gl::kUnitTerrainAerialTable.
    terrain
  };
  explicit AerialTable(Kind kind) : kind_(kind) {}

  /// Computes the table for `view` and the Sun (unit or not, ECEF) and binds it to its unit.
  /// Made on first use (needs a current GL 4.5 context).
  void update(const Atmosphere& atmosphere, const geo::CameraView& view, const glm::dvec3& sunDirectionEcef);

 private:
  Kind kind_;
  gl::Texture texture_;  ///< id 0 until the first update()
  gl::Program program_;
};

}  // namespace og::render
