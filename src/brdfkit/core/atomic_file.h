#pragma once
// Writes a file through a temporary in the same folder, renamed into place only when complete,
// so an interrupted or failed write never leaves a half-written output.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace brdfkit {

// Both check the path first (check_output_file).
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

// InputError naming `path` when no file can be written there: it is a folder, or the folder it
// would go in does not exist. A command checks its output this way before long work, so a typo
// in -o does not cost the work.
void check_output_file(const std::filesystem::path& path);

}  // namespace brdfkit
