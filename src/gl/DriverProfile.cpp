#include "gl/DriverProfile.hpp"

#include <algorithm>

namespace og::gl {

bool isSoftwareRendererName(std::string_view renderer) {
  for (const std::string_view cpu : {"llvmpipe", "softpipe", "swrast", "lavapipe"})
    if (renderer.find(cpu) != std::string_view::npos) return true;
  return false;
}

DriverProfile makeDriverProfile(std::string_view renderer, float deviceMaxAnisotropy) {
  DriverProfile p;
  p.software = isSoftwareRendererName(renderer);
  p.autoSamples = p.software ? 1 : 4;
  p.maxAnisotropy = p.software ? 1.0f : std::max(deviceMaxAnisotropy, 1.0f);
  p.timestampsTimeWork = !p.software;
  p.cpuWaveFft = p.software;
  p.multisampleShadesEveryBlock = p.software;
  p.seaByVisibility = p.software;
  return p;
}

}  // namespace og::gl
