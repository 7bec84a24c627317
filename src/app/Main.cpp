// oceanglobe: planet-scale ocean and terrain globe renderer.
// Exit codes: 0 success, 1 internal failure, 2 bad input (flags, files, paths).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <utility>

#include "app/Commands.hpp"
#include "app/Startup.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Version.hpp"

int main(int argc, char** argv) {
  using namespace og;
  app::noteMainEntry();
  CLI::App app{"oceanglobe - planet-scale ocean and terrain globe renderer", "oceanglobe"};
  app.set_version_flag("--version", std::string("oceanglobe ") + kVersion);
  app.require_subcommand(1);
  bool verbose = false, quiet = false;
  app.add_flag("-v,--verbose", verbose, "print progress and diagnostics");
  app.add_flag("-q,--quiet", quiet, "print errors only");

  // One line per sub-command: its name and the function that runs it once parsed.
  const std::pair<const char*, app::Run> commands[] = {
      {"render", app::addRenderCommand(app)},
      {"bench", app::addBenchCommand(app)},
      {"info", app::addInfoCommand(app)},
      {"record", app::addRecordCommand(app)},
      {"spectrum", app::addSpectrumCommand(app)},
      {"view", app::addViewCommand(app)},
      {"validate", app::addValidateCommand(app)},
      {"path", app::addPathCommand(app)},
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "oceanglobe: %s (see --help)\n", e.what());
    return kExitBadInput;
  }
  log::setLevel(verbose ? log::Level::Info : quiet ? log::Level::Error : log::Level::Warn);

  try {
    for (const CLI::App* sub : app.get_subcommands())
      for (const auto& [name, run] : commands)
        if (sub->get_name() == name) return run();
    return kExitBadInput;
  } catch (const InputError& e) {
    std::fprintf(stderr, "oceanglobe: %s\n", e.what());
    return kExitBadInput;
  } catch (const InternalError& e) {
    std::fprintf(stderr, "oceanglobe: internal error: %s\n", e.what());
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "oceanglobe: out of memory\n");
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "oceanglobe: internal error: %s\n", e.what());
    return kExitInternal;
  }
}
