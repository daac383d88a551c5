#include "brdfkit/measured/load.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>
#include <memory>
#include <string_view>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/alta_slice.h"
#include "brdfkit/measured/cornell.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/rgl_tensor.h"

namespace brdfkit {
namespace {

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

}  // namespace

bool has_measured_extension(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  return ext == ".binary" || ext == ".bsdf" || ext == ".brdf" || ext == ".alta";
}

MeasuredFormat detect_measured_format(const std::filesystem::path& file) {
  const std::string where = file.string();
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) {
    const int e = errno;
    if (e == ENOENT || e == ENOTDIR) throw InputError(where, "no such file");
    throw InputError(where, fmt::format("cannot access: {}", std::strerror(e)));
  }
  if (S_ISDIR(st.st_mode)) throw InputError(where, "is a directory, not a measurement file");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(where, fmt::format("cannot open: {}", std::strerror(errno)));
  char head[64] = {};
  const size_t n = std::fread(head, 1, sizeof head, f.get());
  if (std::ferror(f.get())) throw InputError(where, fmt::format("read error: {}", std::strerror(errno)));
  const std::string_view bytes(head, n);

  if (bytes.starts_with(std::string_view("tensor_file\0", 12))) return MeasuredFormat::Rgl;
  if (n >= 12) {
    std::int32_t dims[3];
    std::memcpy(dims, head, sizeof dims);
    if (dims[0] == merl::kResThetaH && dims[1] == merl::kResThetaD && dims[2] == merl::kResPhiD)
      return MeasuredFormat::Merl;
  }
  if (bytes.starts_with("#DIM")) return MeasuredFormat::Alta;
  // Content gave no answer (e.g. a damaged header): the extension decides, so the format's own
  // reader can say what is wrong.
  const std::string ext = lower_extension(file);
  if (ext == ".binary") return MeasuredFormat::Merl;
  if (ext == ".bsdf") return MeasuredFormat::Rgl;
  if (ext == ".brdf") return MeasuredFormat::Cornell;
  if (ext == ".alta") return MeasuredFormat::Alta;
  return MeasuredFormat::Unknown;
}

std::unique_ptr<MeasuredBrdf> load_measured(const std::filesystem::path& file) {
  switch (detect_measured_format(file)) {
    case MeasuredFormat::Merl:
      return read_merl(file);
    case MeasuredFormat::Rgl:
      return read_rgl(file);
    case MeasuredFormat::Cornell:
      return read_cornell(file);
    case MeasuredFormat::Alta:
      return read_alta_slice(file);
    case MeasuredFormat::Unknown:
      break;
  }
  throw InputError(file.string(),
                   "unrecognized format (expected a MERL .binary, RGL .bsdf, Cornell .brdf or ALTA .alta file)");
}

}  // namespace brdfkit
