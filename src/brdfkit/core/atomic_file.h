#pragma once
// Writes a file through a temporary in the same folder, renamed into place only when complete,
// so an interrupted or failed write never leaves a half-written output: the temporary
// "<file>.tmp.<pid>" is removed when a write fails, and rename(2) within one folder is atomic,
// so a reader sees the old file or the new one, never a mix.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "brdfkit/core/error.h"

namespace brdfkit {

// A file that cannot be written (no space left, a file size limit, no permission): the message
// names the file and the system's reason. An InputError, so interfaces answer it as bad input
// (exit code 2): the user must fix where the output goes, not the data.
class OutputError : public InputError {
 public:
  using InputError::InputError;
};

// Both check the path first (check_output_file); OutputError when the write, the close or the
// rename fails, after removing the temporary.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

// OutputError naming `path` when no file can be written there: it is a folder, or the folder it
// would go in does not exist. A command checks its output this way before long work, so a typo
// in -o does not cost the work.
void check_output_file(const std::filesystem::path& path);

// Removes the temporaries write_file_atomically left for `path` (a writer killed mid-write).
// Only safe while nobody else writes `path`: the caller holds that file's claim or lock.
void remove_temporaries_of(const std::filesystem::path& path);

}  // namespace brdfkit
