#include "brdfkit/core/atomic_file.h"

#include <fstream>

#include <unistd.h>

#include "brdfkit/core/error.h"

namespace brdfkit {

namespace fs = std::filesystem;

void check_output_file(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path.string(), "is a folder; give the path of a file to write");
  const fs::path folder = path.parent_path();
  if (!folder.empty() && !fs::is_directory(folder, ec))
    throw InputError(path.string(), "cannot be written: there is no folder " + folder.string());
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  check_output_file(path);
  const fs::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string(), "cannot open for writing");
    write(out);
    out.flush();
    if (!out) throw InputError(path.string(), "write failed");
    out.close();
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw InputError(path.string(), "cannot be replaced: " + ec.message());
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(contents.data(), std::streamsize(contents.size())); });
}

}  // namespace brdfkit
