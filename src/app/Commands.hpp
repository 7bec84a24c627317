#pragma once
// Sub-commands of the oceanglobe CLI. Each `add*` registers its options on the parent and
// returns the function that runs it once parsing succeeded.
#include <CLI/CLI.hpp>

#include <functional>

namespace og::app {

using Run = std::function<int()>;

Run addRenderCommand(CLI::App& parent);
Run addBenchCommand(CLI::App& parent);
Run addInfoCommand(CLI::App& parent);
Run addRecordCommand(CLI::App& parent);
Run addSpectrumCommand(CLI::App& parent);
Run addViewCommand(CLI::App& parent);
Run addValidateCommand(CLI::App& parent);
Run addPathCommand(CLI::App& parent);

}  // namespace og::app
