#pragma once
// The wind on the GPU (shaders/ocean/wind.glsl): a data::WindLayers stack rasterised to a global
// texture, so the sea's waves, roughness and whitecaps follow the local wind everywhere on the
// globe (the per-wind tables of the waves are render/OceanPatterns'). The texture is the
// shaders' only wind: without layers it holds the constant wind (a stack with no layers, whose
// fallback is that wind), so there is no separate constant-wind path.
#include <memory>

#include "data/WindLayers.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

class WindTextures {
 public:
  /// Needs a current GL context. Starts with the constant default wind (no layers).
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
  /// Layer textures uploaded so far (setLayers and each change of setTime; not the one-cell
  /// constant wind), for tests.
  [[nodiscard]] int uploads() const { return uploads_; }

  /// The strongest wind of the layers, m/s (0 without layers), at any of their time steps: the
  /// waves must hold it, and it stays the same while the layers follow the clock.
  [[nodiscard]] double maxLayerSpeedMs() const { return maxSpeedMs_; }

  /// The wind everywhere while no layers are set (the layers carry their own fallback).
  void setConstantWind(const geo::Wind& wind);
  [[nodiscard]] double constantSpeedMs() const { return constant_.speedMs; }
  /// Where the constant wind blows towards, degrees clockwise from north.
  [[nodiscard]] double constantTowardsDeg() const { return constant_.towardsDeg; }

  /// Binds the texture to its unit (wind.glsl's uWind).
  void bind(const gl::Program& program) const;

 private:
  /// Uploads `raster` (a new texture only when its size changes); returns its strongest wind, m/s.
  double upload(const data::WindRaster& raster);

  std::shared_ptr<const data::WindLayers> layers_;
  data::WindTimeKey key_;  ///< of the winds in the texture
  int width_ = 720;
  int height_ = 360;
  int uploads_ = 0;
  gl::Texture wind_;
  int textureWidth_ = 0;  ///< of wind_ (0: none yet)
  int textureHeight_ = 0;
  double maxSpeedMs_ = 0.0;
  geo::Wind constant_;
  bool constantUploaded_ = false;  ///< wind_ holds constant_ (no layers)
};

}  // namespace og::render
