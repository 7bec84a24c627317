#pragma once
// The deferred sea's surface buffer (shaders/ocean/sea_surface.glsl): an RGBA32UI array
// texture of kLayers layers (kCompactLayers while every frame has used the compact layout),
// each a colour attachment of a framebuffer that shares the frame's depth-stencil texture, so
// that the projected grid's surface pass is depth-tested against the terrain and writes the
// sea's classes into the frame's stencil, or without stencil export into layer 0 (render/
// OceanRenderer).
#include "gl/Objects.hpp"

namespace og::render {

class SeaSurfaceBuffer {
 public:
  static constexpr int kLayers = 6;  ///< SEA_SURFACE_LAYERS
  /// Layers of the compact layout (SEA_SURFACE_COMPACT: no water volume; the class in the
  /// stencil, or in layer 0's footprint bits), the draw buffers beyond them off.
  static constexpr int kCompactLayers = 4;

  /// The depth-stencil texture attached to the bound draw framebuffer and its samples a pixel
  /// (1: a 2D texture); texture 0 where it has none (the default framebuffer, a renderbuffer).
  struct DepthStencil {
    GLuint texture = 0;
    int samples = 1;
  };
  [[nodiscard]] static DepthStencil boundDepthStencil();
  /// Makes the buffer `width` x `height` over `depthStencil` (boundDepthStencil) and binds
  /// its framebuffer with the kLayers draw buffers (kCompactLayers when `compact`); remade only
  /// when the size or the depth-stencil texture changes, or when the first frame without the
  /// compact layout comes (until then it holds only the compact layout's layers).
  void bindForWriting(int width, int height, GLuint depthStencil, bool compact = false);
  /// Between draws of a pass bound with the full layout: the draws that follow write the compact
  /// layout's layers only (`compact`), or all again.
  void drawLayers(bool compact);
  /// Zeroes the layer that holds each pixel's class where the driver cannot export stencil
  /// values (layer 0, the footprint's low bits: ocean/sea_surface.glsl's SEA_CLASS_IN_SURFACE;
  /// 0: no sea drawn), bound for writing.
  void clearClasses() const;
  /// Binds the texture to gl::kUnitSeaSurface for the shading passes.
  void bindForReading() const;

  /// The visibility buffer instead (ocean/sea_visibility.glsl): an R32UI texture, each
  /// sample's grid triangle + 1, over `depthStencil` (of `samples` a pixel: a multisample
  /// texture beyond 1) as bindForWriting; cleared to 0 (no sea) and bound.
  void bindVisibilityForWriting(int width, int height, GLuint depthStencil, int samples = 1);
  /// Binds the visibility texture to gl::kUnitSeaSurface for the shading passes.
  void bindVisibilityForReading() const;
  /// Between draws of a pass bound by bindForWriting: the draws that follow write fragment
  /// output 0 into a single-sampled visibility texture (attachment kLayers of the surface
  /// buffer's framebuffer) and nothing else, until drawLayers. For a frame in classes whose
  /// deep triangles go through the visibility buffer (render/OceanRenderer::drawDeferred).
  void drawVisibility();

 private:
  /// Makes visibility_ `width` x `height` with `samples` unless it is so already.
  void ensureVisibility(int width, int height, int samples);
  /// Attaches `depthStencil` to `fbo` unless it is `*attached` already; checks completeness.
  static void attachDepthStencil(const gl::Framebuffer& fbo, GLuint depthStencil, GLuint* attached);

  gl::Texture layers_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  GLuint depthStencil_ = 0;
  int drawBuffers_ = 0;
  int allocated_ = 0;  ///< layers of layers_: kCompactLayers until a frame wants them all, then kLayers
  gl::Texture visibility_;  ///< bindVisibilityForWriting's, made on first use
  gl::Framebuffer visibilityFbo_;
  int visibilityWidth_ = 0, visibilityHeight_ = 0, visibilitySamples_ = 0;
  GLuint visibilityDepthStencil_ = 0;
  GLuint visibilityInSurface_ = 0;  ///< visibility_ as attached to fbo_ (drawVisibility), 0: none
};

}  // namespace og::render
