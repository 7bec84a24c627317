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

  /// The strongest wind of the layers, m/s (0 without layers): the waves must hold it.
  [[nodiscard]] double maxLayerSpeedMs() const { return maxSpeedMs_; }

  /// The wind everywhere while no layers are set (the layers carry their own fallback).
  void setConstantWind(const geo::Wind& wind);
  [[nodiscard]] double constantSpeedMs() const { return constant_.speedMs; }

  /// Binds the texture to its unit (wind.glsl's uWind).
  void bind(const gl::Program& program) const;

 private:
  void upload(const data::WindRaster& raster);

  std::shared_ptr<const data::WindLayers> layers_;
  gl::Texture wind_;
  double maxSpeedMs_ = 0.0;
  geo::Wind constant_;
  bool constantUploaded_ = false;  ///< wind_ holds constant_ (no layers)
};

}  // namespace og::render
