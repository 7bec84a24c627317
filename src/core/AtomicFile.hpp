#pragma once
// Output files are never left half-written: writers write to a temporary name in the target's
// directory and rename it into place only once complete (rename is atomic on POSIX).
#include <filesystem>
#include <functional>

namespace og {

/// Throws InputError unless `target`'s directory exists and a file can be created there.
/// Call before long work so a bad output path fails fast.
void checkOutputWritable(const std::filesystem::path& target);

/// Calls `write(tmp)` with a fresh temporary path beside `target`, then renames it to `target`.
/// If `write` throws, the temporary file is removed and the exception propagates; an existing
/// `target` is left untouched.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path& tmp)>& write);

}  // namespace og
