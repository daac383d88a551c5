#include "brdfkit/export/scene_files.h"

#include <fmt/format.h>

namespace brdfkit::exporter {

std::string num(double x) { return fmt::format("{:.17g}", x); }

std::string rgb(const std::array<std::vector<double>, 3>& channels, int param, const char* sep) {
  return num(channels[0][size_t(param)]) + sep + num(channels[1][size_t(param)]) + sep + num(channels[2][size_t(param)]);
}

std::string comment_block(const Provenance& p, const std::string& prefix) {
  std::string out;
  for (const std::string& line : provenance_lines(p)) out += prefix + line + "\n";
  return out;
}

std::filesystem::path scene_path(const std::filesystem::path& material_file) {
  std::filesystem::path out = material_file;
  out.replace_filename(material_file.stem().string() + "_scene" + material_file.extension().string());
  return out;
}

}  // namespace brdfkit::exporter
