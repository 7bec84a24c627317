#pragma once
// The wind on the GPU (shaders/ocean/wind.glsl): the data layers rasterised to a global
// texture, so the sea's waves, roughness and whitecaps follow the local wind everywhere on the
// globe (the per-wind tables of the waves are render/OceanPatterns').
#include <memory>

#include "data/WindLayers.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

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

  /// Moves layers that follow the clock to `time` (nullopt: leaves them as they are). The texture is
  /// rebuilt and uploaded only when the layers' steps or quantised blend weights change
  /// (data::WindLayers::timeKey), not every frame.
  void setTime(std::optional<UtcTime> time);
  /// Wind textures uploaded so far (setLayers and each change of setTime), for tests.
  [[nodiscard]] int uploads() const { return uploads_; }

  /// The strongest wind of the layers, m/s (0 without layers), at any of their time steps: the
  /// waves must hold it, and it stays the same while the layers follow the clock.
  [[nodiscard]] double maxLayerSpeedMs() const { return maxSpeedMs_; }

  /// The wind where there are no layers: speed m/s, direction it blows towards, degrees
  /// clockwise from north.
  void setConstantWind(double speedMs, double towardsDeg) {
    constantSpeedMs_ = speedMs;
    constantTowardsDeg_ = towardsDeg;
  }
  [[nodiscard]] double constantSpeedMs() const { return constantSpeedMs_; }

  /// Binds the texture (unit 1) and sets the uniforms of wind.glsl on `program`.
  void bind(const gl::Program& program) const;

 private:
  /// Rasterises and uploads `layers`; returns the strongest wind of the raster, m/s.
  double upload(const data::WindLayers& layers);

  std::shared_ptr<const data::WindLayers> layers_;
  data::WindTimeKey key_;  ///< of the winds in the texture
  int width_ = 720;
  int height_ = 360;
  int uploads_ = 0;
  gl::Texture wind_;
  int textureWidth_ = 1;
  int textureHeight_ = 1;
  double maxSpeedMs_ = 0.0;
  double constantSpeedMs_ = 7.0;
  double constantTowardsDeg_ = 90.0;
};

}  // namespace og::render
