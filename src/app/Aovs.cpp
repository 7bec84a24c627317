#include "app/Aovs.hpp"

#include <algorithm>

namespace og::app {

void addAovOption(CLI::App& cmd, std::vector<std::string>& aovs) {
  cmd.add_option("--aov", aovs,
                 "extra EXR channel (repeatable): whitecap (coverage 0-1) or depth (metres along "
                 "the view ray); needs an .exr output")
      ->check(CLI::IsMember({"whitecap", "depth"}));
}

bool needsAuxiliaryOutputs(const std::vector<std::string>& aovs) {
  return std::find(aovs.begin(), aovs.end(), "whitecap") != aovs.end();
}

std::vector<io::ExrChannel> aovChannels(const render::GlobeRenderer& renderer,
                                        const std::vector<std::string>& aovs) {
  std::vector<io::ExrChannel> channels;
  for (const std::string& name : aovs) {
    if (std::any_of(channels.begin(), channels.end(), [&](const io::ExrChannel& c) { return c.name == name; }))
      continue;
    channels.push_back({name, name == "whitecap" ? renderer.whitecap() : renderer.viewDistance()});
  }
  return channels;
}

}  // namespace og::app
