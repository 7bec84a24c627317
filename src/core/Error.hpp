#pragma once
// Error policy: anything the user handed us (flags, config, data files, output paths) that is
// wrong raises InputError, which the CLI turns into exit code 2 and one line naming the file
// and the problem. Anything else that goes wrong is an InternalError (exit code 1).
#include <stdexcept>
#include <string>

namespace og {

/// Bad user input: a flag out of range, an unreadable or malformed file, an unwritable path.
/// The message is complete and user-facing, e.g. "scene.toml:3: unknown key 'lat_deg'".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A failure that is not the user's fault (GL context, driver, out of memory, a bug).
class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Process exit codes shared by every command.
enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitBadInput = 2, kExitInterrupted = 130 };

}  // namespace og
