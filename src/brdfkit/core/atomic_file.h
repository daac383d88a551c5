#pragma once
// Writes a file through a temporary in the same folder, renamed into place only when complete,
// so an interrupted or failed write never leaves a half-written output.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace brdfkit {

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

}  // namespace brdfkit
