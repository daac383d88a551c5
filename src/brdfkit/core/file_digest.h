#pragma once
// SHA-256 of a file, so a saved fit names exactly the data it was fitted to (DESIGN.md §1).
#include <filesystem>
#include <string>

namespace brdfkit {

// Lower-case hex digest (OpenSSL EVP); InputError when the file cannot be read.
std::string sha256_file(const std::filesystem::path& file);

}  // namespace brdfkit
