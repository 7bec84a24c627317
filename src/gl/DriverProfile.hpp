#pragma once
// What differs between GL drivers, decided once per context from the driver itself and read
// everywhere else: no other folder compares renderer names. The measurements behind each
// choice: docs/architecture.md, "Driver profile".
#include <string_view>

namespace og::gl {

struct DriverProfile {
  /// Renders on the CPU (Mesa's llvmpipe, softpipe, swrast; lavapipe).
  bool software = false;
  /// Samples per pixel that "auto" means: 1 on a software renderer (4 samples cost llvmpipe
  /// 1.6-5x a frame at 1280x720: the sea forward instead of deferred, every sample through
  /// the tone map; docs/performance.md), else 4.
  int autoSamples = 4;
  /// The anisotropy samplers may ask for: 1 on a software renderer (llvmpipe's anisotropic
  /// filtering is ~20x slower and wrong), else what the device offers.
  float maxAnisotropy = 1.0f;
  /// GL timestamp queries time the work (a GPU); on a software renderer they mark when commands
  /// were queued, so pass timers finish (glFinish) at each mark instead.
  bool timestampsTimeWork = true;
  /// GL_ARB_shader_stencil_export: a fragment shader may write the stencil value, so the globe
  /// classifies its pixels in one draw instead of one per class (GlobeRenderer::classifyGlobe).
  /// Off when the driver lacks it, or with OCEANGLOBE_STENCIL_EXPORT=0 (to compare the paths).
  bool stencilExport = false;
  /// The wave patterns' FFTs on the CPU with FFTW, uploaded (render/OceanPatterns): on a
  /// software renderer, whose compute shaders run their barriers as coroutines, that takes a
  /// fifth of the time on the same cores (docs/performance.md, "Eighth session"). On a GPU the
  /// compute shaders. OCEANGLOBE_FFT=cpu or gpu overrides (to compare the paths).
  bool cpuWaveFft = false;
  /// Multisampled draws skip no block for failing the early depth and stencil tests (llvmpipe:
  /// docs/performance.md, "Thirty-fourth session"), so GlobeRenderer draws each of the globe's
  /// parts only where a query found samples and over the blocks that may hold it. On software
  /// renderers; OCEANGLOBE_MSAA_PART_BLOCKS=1 or 0 overrides (to measure a GPU with them).
  bool multisampleShadesEveryBlock = false;
  /// The deferred open sea (one class) through a visibility buffer, its vertices read by the
  /// shading, and multisampled frames' open sea deferred through it too (shaded once a pixel by
  /// compute shaders) instead of forward (render/OceanRenderer, docs/ocean.md): on software
  /// renderers (llvmpipe at 1280x720, sea-4m's surface pass 37 -> 12 ms of one thread; with 4
  /// samples the frame 235-243 -> 184 ms: docs/performance.md, "Thirty-fifth session"); on GPUs
  /// when measured. OCEANGLOBE_SEA_SURFACE=visibility or buffer overrides.
  bool seaByVisibility = false;
};

/// Whether a GL_RENDERER string names a software renderer: the one list of their names.
[[nodiscard]] bool isSoftwareRendererName(std::string_view renderer);

/// The profile of a driver from its GL_RENDERER string and its largest anisotropy.
[[nodiscard]] DriverProfile makeDriverProfile(std::string_view renderer, float deviceMaxAnisotropy);

/// The profile of the current context (built when it was made; see Context::info()). Throws
/// og::InternalError when no context of ours is current.
[[nodiscard]] const DriverProfile& driverProfile();

}  // namespace og::gl
