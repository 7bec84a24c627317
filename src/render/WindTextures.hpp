#pragma once
// The wind on the GPU (shaders/ocean/wind.glsl): the data layers rasterised to a global
// texture, and the wave model's per-wind tables (total slope variance, every wave's amplitude),
// so the sea's roughness and waves follow the local wind everywhere on the globe.
#include <memory>

#include "data/WindLayers.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "ocean/WaveSet.hpp"

namespace og::render {

class WindTextures {
 public:
  /// Needs a current GL context. Starts with a constant wind (no layers).
  WindTextures();

  /// Local winds from data layers (nullptr: the constant wind of each frame). Rasterised to a
  /// global width x height texture; 0.5° by default, finer than any default layer.
  void setLayers(std::shared_ptr<const data::WindLayers> layers, int width = 720, int height = 360);
  [[nodiscard]] bool hasLayers() const { return layers_ != nullptr; }
  [[nodiscard]] const data::WindLayers* layers() const { return layers_.get(); }

  /// The per-wind tables for this wave set (rebuilt only when the set changes).
  void setWaveSet(const ocean::WaveSet& set);

  /// Binds the textures (units 1 and 10) and sets the uniforms of wind.glsl on `program`;
  /// `speedMs`/`directionDeg` is the constant wind used when there are no layers.
  void bind(const gl::Program& program, double speedMs, double directionDeg) const;

 private:
  std::shared_ptr<const data::WindLayers> layers_;
  gl::Texture wind_;
  gl::Texture table_;
  double tableStepMs_ = 1.0;
  ocean::WaveSetParams tableFor_;
  bool tableBuilt_ = false;
};

}  // namespace og::render
