#pragma once
// Parts of the program loaded only when first needed: the GDAL rasters (src/data,
// oceanglobe-gdal.so) and the FFmpeg video (src/io, oceanglobe-ffmpeg.so). Linked into the
// executable, GDAL's and FFmpeg's ~150 shared libraries (224 in all against 76 without) cost
// every start ~100-200 ms of the dynamic loader's relocations before main, though a cached
// start reads neither (docs/performance.md, "Forty-first session"); as modules they cost only
// the commands that read a GDAL raster or write an MP4.
//
// A module is built from this project's sources with the same compiler, so its interface is a
// C++ object (an abstract class the module implements) returned by one extern "C" entry point;
// exceptions (og::InputError, og::InternalError) cross it as thrown. It does not link og_core:
// what it needs of the program (the log) comes through the Host it is handed.
#include <string_view>

#include "core/Log.hpp"

namespace og::plugin {

/// What the program lends a module.
struct Host {
  /// The build both sides must come from (OG_PLUGIN_ABI: the project's version and a token
  /// drawn once per build tree): a module from another build has other classes behind the
  /// same names, so it refuses the host (first member, never moved).
  const char* abi;
  void (*write)(log::Level level, std::string_view message);  ///< og::log::write
  log::Level (*level)();                                      ///< og::log::level
};

/// The signature of a module's entry point: returns its interface object (owned by the module,
/// alive as long as the process) for the given host, or nullptr when the host's build is not
/// the module's (acceptHost).
using Entry = void* (*)(const Host* host);

/// The entry point's name in every module.
inline constexpr const char* kEntrySymbol = "oceanglobe_plugin_entry";

/// Loads module `name` ("oceanglobe-gdal": `oceanglobe-gdal.so`) once per process and returns
/// its interface object. Looks next to the running executable first, then in the build tree it
/// was built in (OG_PLUGIN_DIR: the tests' executables live in a subfolder). Thread-safe.
/// Throws og::InternalError naming the file and the loader's message when it cannot be loaded
/// (a broken installation, not the user's input), also when it is another build's. `purpose`
/// says what needed it ("reading GeoTIFF and other GDAL rasters").
void* load(std::string_view name, std::string_view purpose);

/// The module's side, first thing in its entry point: false when `host` comes from another
/// build (its abi is not this module's OG_PLUGIN_ABI); else stores it, whose log the module's
/// og::log::write forwards to (core/PluginLog.cpp, linked into modules instead of core/Log.cpp).
bool acceptHost(const Host* host);

}  // namespace og::plugin
