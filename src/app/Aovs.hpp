#pragma once
// `--aov NAME` (render, record): extra named channels in OpenEXR outputs, next to R, G, B, A.
//   whitecap  whitecap coverage of the pixel, [0, 1] (GlobeRenderer::whitecap)
//   depth     distance from the eye to the surface along the pixel's ray, metres; 1e10 for the
//             sky (GlobeRenderer::viewDistance)
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::app {

/// Registers the repeatable --aov option (whitecap | depth) on `cmd`.
void addAovOption(CLI::App& cmd, std::vector<std::string>& aovs);

/// True when one of `aovs` needs FrameInput::auxiliaryOutputs.
[[nodiscard]] bool needsAuxiliaryOutputs(const std::vector<std::string>& aovs);

/// The channels of `aovs` from the renderer's last frame (each name once, in the order given).
[[nodiscard]] std::vector<io::ExrChannel> aovChannels(const render::GlobeRenderer& renderer,
                                                      const std::vector<std::string>& aovs);

}  // namespace og::app
