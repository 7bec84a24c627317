// A module as another build of oceanglobe would make it: its build token (OG_PLUGIN_ABI,
// core/Plugin.hpp) is not this build's. Plugin.AModuleOfAnotherBuildIsRefused loads it.
#include "core/Plugin.hpp"

extern "C" __attribute__((visibility("default"))) void* oceanglobe_plugin_entry(const og::plugin::Host* host) {
  static int object = 0;
  return og::plugin::acceptHost(host) ? &object : nullptr;
}
