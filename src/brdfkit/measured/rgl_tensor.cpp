#include "brdfkit/measured/rgl_tensor.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/rgl_coordinates.h"
#include "brdfkit/measured/spectral_rgb.h"

namespace brdfkit {

using rgl::elevation;
using rgl::phi2u;
using rgl::theta2u;
using rgl::u2phi;
using rgl::u2theta;

namespace {

// Mitsuba's Struct::Type codes as written in tensor_file headers.
enum class TensorType : std::uint8_t { Invalid = 0, UInt8, Int8, UInt16, Int16, UInt32, Int32, UInt64, Int64, Float16, Float32, Float64 };

size_t type_size(std::uint8_t t) {
  switch (TensorType(t)) {
    case TensorType::UInt8: case TensorType::Int8: return 1;
    case TensorType::UInt16: case TensorType::Int16: case TensorType::Float16: return 2;
    case TensorType::UInt32: case TensorType::Int32: case TensorType::Float32: return 4;
    case TensorType::UInt64: case TensorType::Int64: case TensorType::Float64: return 8;
    default: return 0;
  }
}

struct Field {
  std::uint8_t type = 0;
  std::uint64_t offset = 0;
  std::vector<std::uint64_t> shape;
  size_t count() const {
    size_t n = 1;
    for (auto s : shape) n *= size_t(s);
    return n;
  }
};

// Little-endian reader over the whole file with bounds checks (truncation → InputError).
class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, const std::string& where) : b_(bytes), where_(where) {}
  template <class T> T get() {
    need(sizeof(T));
    T v = 0;
    for (size_t k = 0; k < sizeof(T); ++k) v = T(v | (T(b_[pos_ + k]) << (8 * k)));
    pos_ += sizeof(T);
    return v;
  }
  std::string bytes(size_t n) {
    need(n);
    std::string s(reinterpret_cast<const char*>(b_.data() + pos_), n);
    pos_ += n;
    return s;
  }

 private:
  void need(size_t n) const {
    if (pos_ + n > b_.size())
      throw InputError(where_, fmt::format("truncated header: needs {} bytes at offset {}, file has {}", n, pos_, b_.size()));
  }
  const std::vector<std::uint8_t>& b_;
  std::string where_;
  size_t pos_ = 0;
};

// Whether a field of `shape` with entries of `entry_bytes` bytes fits in `room` bytes: Π shape ≤
// ⌊room / entry_bytes⌋, tested by dividing, so no product wraps. (A wrapped product passes a bounds
// check while the shape still sizes vectors and loops: 2^24 × 2^24 × 2^14 float32 is 2^64 bytes,
// 0 once wrapped.)
bool fits_in(const std::vector<std::uint64_t>& shape, size_t entry_bytes, size_t room) {
  if (std::find(shape.begin(), shape.end(), 0) != shape.end()) return true;  // no entries at all
  std::uint64_t entries = room / entry_bytes;
  for (const std::uint64_t s : shape) {
    if (s > entries) return false;
    entries /= s;
  }
  return true;
}

std::vector<float> floats(const std::vector<std::uint8_t>& bytes, const Field& f) {
  std::vector<float> v(f.count());
  // The format is little-endian like every machine brdfkit builds for; copy bytes as they are.
  static_assert(std::endian::native == std::endian::little, "tensor_file reader assumes a little-endian host");
  // A field with a zero dimension has no entries; an empty vector's data() may be null, which
  // memcpy may not be given even for 0 bytes.
  if (!v.empty()) std::memcpy(v.data(), bytes.data() + f.offset, v.size() * sizeof(float));
  return v;
}

std::string shape_string(const std::vector<std::uint64_t>& s) {
  return fmt::format("[{}]", fmt::join(s, ","));
}

// "[i0,i1,…]": the position of flat entry `flat` in a row-major table of `shape`.
std::string index_string(const std::vector<std::uint64_t>& shape, size_t flat) {
  std::vector<std::uint64_t> index(shape.size());
  for (size_t d = shape.size(); d-- > 0;) {
    index[d] = flat % shape[d];
    flat /= shape[d];
  }
  return shape_string(index);
}

// A table entry as a message shows it: NaN, +Inf, -Inf or its shortest decimal form.
std::string describe(float x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "+Inf" : "-Inf";
  return fmt::format("{}", x);
}

// One float32 table of the file and the rules it must follow; a broken rule is an InputError
// naming the file, the field and the first bad entry (flat and per-dimension index).
struct TableView {
  const std::string& path;
  std::string name;
  const Field& field;
  std::span<const float> values;

  [[noreturn]] void refuse(size_t k, std::string_view rule) const {
    throw InputError(path, fmt::format("field '{}' entry {} {} is {}: {}", name, k, index_string(field.shape, k),
                                       describe(values[k]), rule));
  }
  template <class Ok> void require_each(Ok ok, std::string_view rule) const {
    for (size_t k = 0; k < values.size(); ++k)
      if (!ok(values[k])) refuse(k, rule);
  }
  void require_finite() const { require_each([](float x) { return std::isfinite(x); }, "must be finite"); }
  void require_non_negative() const { require_each([](float x) { return x >= 0; }, "must be ≥ 0 (a density)"); }
  void require_increasing() const {
    for (size_t k = 1; k < values.size(); ++k)
      if (!(values[k] > values[k - 1]))
        refuse(k, fmt::format("must be greater than entry {} ({})", k - 1, describe(values[k - 1])));
  }
  // Entries [begin, end) must not all be 0; `why` says what a zero block would break.
  void require_not_all_zero(size_t begin, size_t end, std::string_view why) const {
    if (std::any_of(values.begin() + std::ptrdiff_t(begin), values.begin() + std::ptrdiff_t(end), [](float x) { return x != 0; }))
      return;
    throw InputError(path, fmt::format("field '{}' entries {} {} to {} {} are all 0: {}", name, begin, index_string(field.shape, begin),
                                       end - 1, index_string(field.shape, end - 1), why));
  }
};

// Applies `rules` to the float32 field `name` after checking that every entry is finite. A field
// that is absent or not float32 is left to the reader's own checks.
template <class Rules>
void check_table(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::map<std::string, Field>& fields,
                 const char* name, Rules rules) {
  const auto it = fields.find(name);
  if (it == fields.end() || it->second.type != std::uint8_t(TensorType::Float32)) return;
  const std::vector<float> v = floats(bytes, it->second);
  const TableView t{path, name, it->second, v};
  t.require_finite();
  rules(t);
}

// The angle grids and wavelengths: within their domain and increasing. float(π/2) and float(π)
// round up, so a file's own float π/2 (the horizon node) passes.
void check_grids(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::map<std::string, Field>& fields) {
  const float half_pi = float(kPi / 2), pi = float(kPi);
  check_table(path, bytes, fields, "theta_i", [&](const TableView& t) {
    t.require_each([&](float x) { return x >= 0 && x <= half_pi; }, "must lie in [0, π/2]");
    t.require_increasing();
  });
  check_table(path, bytes, fields, "phi_i", [&](const TableView& t) {
    t.require_each([&](float x) { return x >= -pi && x <= pi; }, "must lie in [-π, π]");
    t.require_increasing();
  });
  check_table(path, bytes, fields, "wavelengths", [](const TableView& t) {
    t.require_each([](float x) { return x > 0; }, "must be > 0 (nm)");
    t.require_increasing();
  });
}

// σ divides every value; D and the VNDF are densities, and each θi slice of the VNDF is a warp.
// The VNDF's shape (4 dimensions, slices of at least 2 × 2) must have been checked.
void check_microfacet_tables(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::map<std::string, Field>& fields) {
  check_table(path, bytes, fields, "sigma",
              [](const TableView& t) { t.require_each([](float x) { return x > 0; }, "must be > 0 (σ(ω) divides every value)"); });
  check_table(path, bytes, fields, "ndf", [](const TableView& t) {
    t.require_non_negative();
    t.require_not_all_zero(0, t.values.size(), "D(h) would make every value 0");
  });
  check_table(path, bytes, fields, "vndf", [](const TableView& t) {
    t.require_non_negative();
    const size_t slice = size_t(t.field.shape[2] * t.field.shape[3]);
    for (size_t begin = 0; begin < t.values.size(); begin += slice)
      t.require_not_all_zero(begin, begin + slice, "a slice of the VNDF with no density is no warp");
  });
}

// The tables brdfkit reads, checked where the format defines their domain (DESIGN.md §2, Dupuy &
// Jakob 2018 §5–6) before any reaches a warp: there a NaN spreads through every CDF, and an angle
// outside its domain (a negative θi) makes a look-up index outside the tables. Colour tables may
// hold negative noise (DESIGN.md §2): finite is all they must be.
void check_tables(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::map<std::string, Field>& fields) {
  check_grids(path, bytes, fields);
  check_microfacet_tables(path, bytes, fields);
  for (const char* name : {"luminance", "rgb", "spectra"}) check_table(path, bytes, fields, name, [](const TableView&) {});
}

// The header and field table of a tensor_file (Dupuy & Jakob 2018's format, Mitsuba 3
// src/core/tensor.cpp): magic, version 1.0, then per field its name, rank, type, offset and shape,
// each field's data checked to lie inside the file.
std::map<std::string, Field> read_fields(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  Reader r(bytes, path);
  const std::string magic = r.bytes(12);
  if (std::memcmp(magic.data(), "tensor_file\0", 12) != 0)
    throw InputError(path, "not an RGL tensor_file (bad magic; expected \"tensor_file\\0\")");
  const int major = r.get<std::uint8_t>(), minor = r.get<std::uint8_t>();
  if (major != 1 || minor != 0) throw InputError(path, fmt::format("unsupported tensor_file version {}.{} (expected 1.0)", major, minor));
  const std::uint32_t n_fields = r.get<std::uint32_t>();
  if (n_fields > 1000) throw InputError(path, fmt::format("implausible field count {}", n_fields));
  std::map<std::string, Field> fields;
  for (std::uint32_t k = 0; k < n_fields; ++k) {
    const std::string name = r.bytes(r.get<std::uint16_t>());
    Field f;
    const std::uint16_t ndim = r.get<std::uint16_t>();
    f.type = r.get<std::uint8_t>();
    f.offset = r.get<std::uint64_t>();
    for (std::uint16_t d = 0; d < ndim; ++d) f.shape.push_back(r.get<std::uint64_t>());
    const size_t ts = type_size(f.type);
    if (ts == 0) throw InputError(path, fmt::format("field '{}': unknown type code {}", name, f.type));
    for (auto s : f.shape)
      if (s > (1u << 24)) throw InputError(path, fmt::format("field '{}': implausible dimension {}", name, s));
    if (f.offset > bytes.size() || !fits_in(f.shape, ts, bytes.size() - f.offset))
      throw InputError(path, fmt::format("field '{}': data (shape {} of {}-byte entries at offset {}) extend past the end of the file "
                                         "({} bytes): truncated?",
                                         name, shape_string(f.shape), ts, f.offset, bytes.size()));
    fields[name] = std::move(f);
  }
  return fields;
}

// Field `name`, which must be present with `ndim` dimensions of `type`.
const Field& required_field(const std::string& path, const std::map<std::string, Field>& fields, const std::string& name,
                            TensorType type, size_t ndim) {
  auto it = fields.find(name);
  if (it == fields.end()) throw InputError(path, fmt::format("missing field '{}'", name));
  if (it->second.type != std::uint8_t(type) || it->second.shape.size() != ndim)
    throw InputError(path, fmt::format("field '{}': expected {} dimension(s) of type code {}, found shape {} type {}", name, ndim,
                                       int(type), shape_string(it->second.shape), it->second.type));
  return it->second;
}

// The colour table as three channel tables of nphi × nt × grid × grid values: `rgb`, or `spectra` +
// `wavelengths` converted node by node (spectral_rgb.h).
struct ColourTable {
  std::array<std::vector<float>, 3> rgb;
  size_t negative_values = 0;  // entries < 0 (measurement noise, kept: DESIGN.md §2)
  bool spectral = false;
};
ColourTable read_colour_table(const std::vector<std::uint8_t>& bytes, const std::string& path,
                              const std::map<std::string, Field>& fields, size_t nphi, size_t nt, size_t grid) {
  const size_t cells = grid * grid, slices = nphi * nt;
  ColourTable out;
  for (auto& c : out.rgb) c.resize(slices * cells);
  if (fields.count("rgb")) {
    const Field& f = required_field(path, fields, "rgb", TensorType::Float32, 5);
    if (f.shape[0] != nphi || f.shape[1] != nt || f.shape[2] != 3 || f.shape[3] != grid || f.shape[4] != grid)
      throw InputError(path, fmt::format("field 'rgb' has shape {}, expected [{},{},3,{},{}]", shape_string(f.shape), nphi, nt, grid, grid));
    const std::vector<float> v = floats(bytes, f);
    for (size_t t = 0; t < slices; ++t)
      for (size_t c = 0; c < 3; ++c)
        for (size_t i = 0; i < cells; ++i) {
          const float x = v[(t * 3 + c) * cells + i];
          out.rgb[c][t * cells + i] = x;
          out.negative_values += x < 0;
        }
    return out;
  }
  if (!fields.count("spectra")) throw InputError(path, "missing field 'rgb' (or 'spectra' + 'wavelengths')");
  out.spectral = true;
  const Field& f = required_field(path, fields, "spectra", TensorType::Float32, 5);
  const Field& wf = required_field(path, fields, "wavelengths", TensorType::Float32, 1);
  const std::vector<float> wl_f = floats(bytes, wf);
  const size_t nl = wl_f.size();
  if (nl == 0) throw InputError(path, "field 'wavelengths' is empty: 'spectra' needs at least one wavelength");
  if (f.shape[0] != nphi || f.shape[1] != nt || f.shape[2] != nl || f.shape[3] != grid || f.shape[4] != grid)
    throw InputError(path, fmt::format("field 'spectra' has shape {}, expected [{},{},{},{},{}]", shape_string(f.shape), nphi, nt, nl,
                                       grid, grid));
  const std::vector<double> wl(wl_f.begin(), wl_f.end());
  const Eigen::MatrixXd m = default_spectrum_to_rgb().matrix(wl);
  const std::vector<float> v = floats(bytes, f);
  Eigen::VectorXd s{Eigen::Index(nl)};
  for (size_t t = 0; t < slices; ++t)
    for (size_t i = 0; i < cells; ++i) {
      for (size_t l = 0; l < nl; ++l) {
        s[Eigen::Index(l)] = v[(t * nl + l) * cells + i];
        out.negative_values += s[Eigen::Index(l)] < 0;
      }
      const Eigen::Vector3d c = m * s;
      for (size_t k = 0; k < 3; ++k) out.rgb[k][t * cells + i] = float(c[Eigen::Index(k)]);
    }
  return out;
}

// The incidence-azimuth layout of Mitsuba 3's `measured` (src/bsdfs/measured.cpp): at most two
// phi_i entries is an isotropic file (half-vector azimuths relative to φi); more is anisotropic,
// its phi_i range one of 1, 2 or 4 copies that fill the circle. Files whose range is not
// [-π, -π + 2π/copies] would be misread by that plugin's mirroring, so they are refused.
int azimuth_reduction(const std::string& path, const std::vector<float>& phi_i) {
  if (phi_i.size() <= 2) return 1;
  const double range = double(phi_i.back()) - double(phi_i.front());
  const int reduction = int(std::rint(2 * kPi / range));
  if (reduction != 1 && reduction != 2 && reduction != 4)
    throw InputError(path, fmt::format("field 'phi_i' spans {:.4f} rad: an anisotropic file spans 2π, π or π/2 (1, 2 or 4 copies "
                                       "fill the circle)",
                                       range));
  constexpr double kTolerance = 1e-3;  // float nodes
  if (std::abs(phi_i.front() + kPi) > kTolerance || std::abs(range - 2 * kPi / reduction) > kTolerance)
    throw InputError(path, fmt::format("field 'phi_i' runs from {:.4f} to {:.4f}: an anisotropic file holding 1/{} of the azimuths "
                                       "runs from -π to {:.4f}",
                                       phi_i.front(), phi_i.back(), reduction, -kPi + 2 * kPi / reduction));
  return reduction;
}

}  // namespace

RglBrdf::RglBrdf(const std::filesystem::path& file) : path_(file.string()) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(path_, "cannot open file");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::map<std::string, Field> fields = read_fields(bytes, path_);
  auto field = [&](const std::string& name, TensorType type, size_t ndim) -> const Field& {
    return required_field(path_, fields, name, type, ndim);
  };
  const Field& theta_f = field("theta_i", TensorType::Float32, 1);
  const Field& phi_f = field("phi_i", TensorType::Float32, 1);
  const Field& sigma_f = field("sigma", TensorType::Float32, 2);
  const Field& ndf_f = field("ndf", TensorType::Float32, 2);
  const Field& vndf_f = field("vndf", TensorType::Float32, 4);
  const Field& lum_f = field("luminance", TensorType::Float32, 4);
  const Field& jac_f = field("jacobian", TensorType::UInt8, 1);
  if (auto it = fields.find("description"); it != fields.end() && it->second.type == std::uint8_t(TensorType::UInt8))
    description_ = std::string(reinterpret_cast<const char*>(bytes.data() + it->second.offset), it->second.count());

  theta_i_ = floats(bytes, theta_f);
  phi_i_ = floats(bytes, phi_f);
  const size_t nt = theta_i_.size(), np = phi_i_.size();
  if (np < 1) throw InputError(path_, "field 'phi_i' needs at least 1 entry");
  if (nt < 2) throw InputError(path_, "field 'theta_i' needs at least 2 entries");
  if (jac_f.count() != 1) throw InputError(path_, "field 'jacobian' must hold one value");
  jacobian_ = bytes[jac_f.offset] != 0;

  const auto& vs = vndf_f.shape;
  const auto& ls = lum_f.shape;
  if (vs[0] != np || vs[1] != nt || vs[2] < 2 || vs[3] < 2)
    throw InputError(path_, fmt::format("field 'vndf' has shape {}, expected [{},{},ny,nx]", shape_string(vs), np, nt));
  if (ls[0] != np || ls[1] != nt || ls[2] != ls[3] || ls[2] < 2)
    throw InputError(path_, fmt::format("field 'luminance' has shape {}, expected [{},{},n,n]", shape_string(ls), np, nt));
  for (const Field* f : {&sigma_f, &ndf_f})
    if (f->shape[0] < 2 || f->shape[1] < 2) throw InputError(path_, fmt::format("fields 'sigma'/'ndf' need at least 2 x 2 entries, found {}", shape_string(f->shape)));
  check_tables(path_, bytes, fields);
  isotropic_ = np <= 2;
  reduction_ = azimuth_reduction(path_, phi_i_);
  grid_ = int(ls[2]);
  ColourTable colour = read_colour_table(bytes, path_, fields, np, nt, size_t(grid_));
  spectral_ = colour.spectral;
  negative_values_ = colour.negative_values;

  const std::vector<std::vector<float>> params = {phi_i_, theta_i_};
  ndf_ = MarginalWarp2D(floats(bytes, ndf_f).data(), int(ndf_f.shape[1]), int(ndf_f.shape[0]), {}, false);
  sigma_ = MarginalWarp2D(floats(bytes, sigma_f).data(), int(sigma_f.shape[1]), int(sigma_f.shape[0]), {}, false);
  vndf_ = MarginalWarp2D(floats(bytes, vndf_f).data(), int(vs[3]), int(vs[2]), params, true);
  luminance_raw_ = floats(bytes, lum_f);
  luminance_ = MarginalWarp2D(luminance_raw_.data(), grid_, grid_, params, false);
  for (size_t c = 0; c < 3; ++c) rgb_[c] = MarginalWarp2D(colour.rgb[c].data(), grid_, grid_, params, false);
  rgb_raw_ = std::move(colour.rgb);
}

std::string RglBrdf::dimensions() const {
  const std::string azimuths =
      isotropic_ ? "" : fmt::format("{} phi_i (anisotropic, 1/{} of the azimuths) x ", phi_i_.size(), reduction_);
  return fmt::format("{}{} theta_i x {}x{} {} grid (jacobian {}){}", azimuths, theta_i_.size(), grid_, grid_,
                     spectral_ ? "spectral->rgb" : "rgb", jacobian_ ? 1 : 0, description_.empty() ? "" : ", \"" + description_ + "\"");
}

RglBrdf::Fold RglBrdf::fold(const Vec3d& wc) const {
  if (reduction_ < 2) return {};
  // Mitsuba 3 `measured`: mulsign_neg(v, s) negates v unless s's sign bit is set.
  const double sy = std::signbit(wc.y()) ? 1.0 : -1.0;
  const double sx = reduction_ == 4 ? (std::signbit(wc.x()) ? 1.0 : -1.0) : sy;
  return {sx, sy};
}

std::optional<Rgb> RglBrdf::eval(const Vec3d& wi, const Vec3d& wo) const { return eval_conditioned(wi, wo, true); }

namespace {
// The part of a look-up that depends on ωc alone (folded into the stored azimuths): its angles, the
// interpolation weights of its (φc, θc) between the tables' nodes, σ(ωc). Computed once for all
// samples that share ωc.
struct Conditioning {
  double params[2];
  MarginalWarp2D::Weights weights;
  double sigma;
};

Conditioning condition_on(const Vec3d& wc, const MarginalWarp2D& vndf, const MarginalWarp2D& sigma) {
  const double theta_c = elevation(wc), phi_c = std::atan2(wc.y(), wc.x());
  Conditioning c;
  c.params[0] = phi_c;
  c.params[1] = theta_c;
  c.weights = vndf.weights(c.params);  // every table conditioned on (φc, θc) has vndf's nodes
  c.sigma = sigma.eval(Vec2d(theta2u(theta_c), phi2u(phi_c)));
  return c;
}

// What eval needs of a direction pair: table coordinates and the factor D/(4σ(ωc) cos θ).
struct Lookup {
  Vec2d sample;
  double factor;
};

// The half vector's unit-square coordinates: its azimuth relative to ωc's in an isotropic file
// (Dupuy & Jakob 2018 §6), absolute in an anisotropic one (Mitsuba 3 `measured`).
Vec2d half_vector_coordinates(const Vec3d& m, double phi_c, bool isotropic) {
  Vec2d u_m(theta2u(elevation(m)), phi2u(std::atan2(m.y(), m.x()) - (isotropic ? phi_c : 0.0)));
  u_m.y() -= std::floor(u_m.y());
  return u_m;
}

// The tables a look-up reads, shared by every evaluation (single pairs and eval_row), so they agree
// by construction. The pair must already be folded (RglBrdf::fold).
struct LookupTables {
  const MarginalWarp2D& vndf;
  const MarginalWarp2D& ndf;
  bool jacobian, isotropic;

  std::optional<Lookup> operator()(const Vec3d& wc, const Conditioning& c, const Vec3d& wx, bool cosine_of_other) const {
    if (!(wc.z() > 0) || !(wx.z() > 0)) return std::nullopt;
    const Vec2d u_m = half_vector_coordinates((wc + wx).normalized(), c.params[0], isotropic);
    Lookup r;
    r.sample = vndf.invert(u_m, c.weights).first;
    const double cos_theta = cosine_of_other ? wx.z() : wc.z();
    // DESIGN.md §2: ρ = table · D(h) / (4 σ(ωc) cos θx); with jacobian = 0 the table holds ρ·cos θx.
    r.factor = jacobian ? ndf.eval(u_m) / (4 * c.sigma * cos_theta) : 1 / cos_theta;
    return r;
  }
};
}  // namespace

std::optional<Rgb> RglBrdf::eval_conditioned(const Vec3d& wc_in, const Vec3d& wx_in, bool cosine_of_other) const {
  if (!(wc_in.z() > 0) || !(wx_in.z() > 0)) return std::nullopt;
  const Fold f = fold(wc_in);
  const Vec3d wc = f(wc_in), wx = f(wx_in);
  const Conditioning c = condition_on(wc, vndf_, sigma_);
  const auto l = LookupTables{vndf_, ndf_, jacobian_, isotropic_}(wc, c, wx, cosine_of_other);
  if (!l) return std::nullopt;
  Rgb v;
  for (int k = 0; k < 3; ++k) v[k] = rgb_[size_t(k)].eval(l->sample, c.weights);
  return Rgb(v * l->factor);
}

void RglBrdf::eval_row(const Vec3d& wi_in, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const {
  out.assign(wo.size(), std::nullopt);
  if (!(wi_in.z() > 0)) return;
  const Fold f = fold(wi_in);
  const Vec3d wi = f(wi_in);
  const Conditioning c = condition_on(wi, vndf_, sigma_);
  const LookupTables lookup{vndf_, ndf_, jacobian_, isotropic_};
  for (size_t k = 0; k < wo.size(); ++k) {
    const auto l = lookup(wi, c, f(wo[k]), true);
    if (!l) continue;
    const MarginalWarp2D::Patch patch = rgb_[0].locate(l->sample);  // the colour tables share their grid
    Rgb v;
    for (int ch = 0; ch < 3; ++ch) v[ch] = rgb_[size_t(ch)].eval(patch, c.weights);
    out[k] = Rgb(v * l->factor);
  }
}

std::optional<double> RglBrdf::eval_luminance(const Vec3d& wi_in, const Vec3d& wo_in) const {
  if (!(wi_in.z() > 0) || !(wo_in.z() > 0)) return std::nullopt;
  const Fold f = fold(wi_in);
  const Vec3d wi = f(wi_in);
  const Conditioning c = condition_on(wi, vndf_, sigma_);
  const auto l = LookupTables{vndf_, ndf_, jacobian_, isotropic_}(wi, c, f(wo_in), true);
  if (!l) return std::nullopt;
  return luminance_.eval(l->sample, c.weights) * l->factor;
}

std::optional<Vec2d> RglBrdf::table_coordinates(const Vec3d& wc_in, const Vec3d& wx_in) const {
  if (!(wc_in.z() > 0) || !(wx_in.z() > 0)) return std::nullopt;
  const Fold f = fold(wc_in);
  const Vec3d wc = f(wc_in);
  const auto l = LookupTables{vndf_, ndf_, jacobian_, isotropic_}(wc, condition_on(wc, vndf_, sigma_), f(wx_in), true);
  if (!l) return std::nullopt;
  return l->sample;
}

Rgb RglBrdf::rgb_node(size_t slice, int y, int x) const {
  const size_t i = slice * size_t(grid_) * size_t(grid_) + size_t(y) * size_t(grid_) + size_t(x);
  return Rgb(rgb_raw_[0][i], rgb_raw_[1][i], rgb_raw_[2][i]);
}

double RglBrdf::luminance_node(size_t slice, int y, int x) const {
  return luminance_raw_[slice * size_t(grid_) * size_t(grid_) + size_t(y) * size_t(grid_) + size_t(x)];
}

double RglBrdf::ndf(const Vec3d& m) const {
  return ndf_.eval(Vec2d(theta2u(elevation(m)), phi2u(std::atan2(m.y(), m.x()))));
}

double RglBrdf::sigma(const Vec3d& w) const {
  return sigma_.eval(Vec2d(theta2u(elevation(w)), phi2u(std::atan2(w.y(), w.x()))));
}

Vec3d RglBrdf::incidence(size_t slice) const {
  return spherical_direction(double(theta_i_[slice % theta_i_.size()]), double(phi_i_[slice / theta_i_.size()]));
}

RglBrdf::NodeWarp RglBrdf::node_warp(size_t slice, const Vec2d& u) const {
  const Vec3d wc = incidence(slice);
  const double phi_c = phi_i_[slice / theta_i_.size()];
  const double params[2] = {phi_c, theta_i_[slice % theta_i_.size()]};
  const auto [u_m, pdf] = vndf_.sample(u, params);
  const Vec3d m = spherical_direction(u2theta(u_m.x()), u2phi(u_m.y()) + (isotropic_ ? phi_c : 0.0));
  const Vec3d wx = reflect(wc, m).normalized();
  // |dωx/du|: Dupuy & Jakob 2018 §5 (Mitsuba 3 `measured`): dωm = 2π² u_m,x sin θm du_m,
  // dωx = 4 (ωc·m) dωm, du_m = pdf du.
  const double jac = rgl::half_vector_jacobian(u_m.x()) * 4 * wc.dot(m);
  return {u_m, wc, wx, pdf > 0 && wx.z() > 0 ? jac / pdf : 0.0};
}

std::optional<std::pair<Vec3d, Vec3d>> RglBrdf::node_directions(size_t slice, int y, int x) const {
  const NodeWarp n = node_warp(slice, Vec2d(double(x) / (grid_ - 1), double(y) / (grid_ - 1)));
  if (!(n.wx.z() > 0)) return std::nullopt;
  return std::pair{n.wc, n.wx};
}

std::vector<double> RglBrdf::azimuth_shares() const {
  const size_t np = phi_i_.size();
  if (np == 1) return {1.0};
  // Trapezoid widths of the phi_i nodes over their range, one of `reduction_` copies of the circle.
  std::vector<double> share(np);
  for (size_t p = 0; p < np; ++p) {
    const double lo = phi_i_[p == 0 ? 0 : p - 1], hi = phi_i_[p + 1 == np ? p : p + 1];
    share[p] = 0.5 * (hi - lo) / (double(phi_i_.back()) - double(phi_i_.front())) / reduction_;
  }
  return share;
}

// The images of a stored pair under the file's azimuthal symmetry (the inverse of fold()): a half
// turn for 1/2 of the azimuths, the mirrors about both axes for 1/4.
std::vector<RglBrdf::Fold> RglBrdf::images() const {
  if (reduction_ == 2) return {{1, 1}, {-1, -1}};
  if (reduction_ == 4) return {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  return {{1, 1}};
}

double RglBrdf::node_weight(size_t slice, int y, int x) const {
  // The solid angle of wo over the node's cell [x ± ½, y ± ½] ∩ [0,1]² of the unit square, by a 4 × 4
  // midpoint rule. (Trapezoid weights at the nodes would give the x = 0 column, h = n, no weight:
  // the specular peak of glossy files would be lost.)
  constexpr int kSub = 4;
  const double du = 1.0 / (grid_ - 1);
  const double x0 = std::max(0.0, (x - 0.5) * du), x1 = std::min(1.0, (x + 0.5) * du);
  const double y0 = std::max(0.0, (y - 0.5) * du), y1 = std::min(1.0, (y + 0.5) * du);
  double weight = 0;
  for (int j = 0; j < kSub; ++j)
    for (int i = 0; i < kSub; ++i)
      weight += node_warp(slice, Vec2d(x0 + (i + 0.5) / kSub * (x1 - x0), y0 + (j + 0.5) / kSub * (y1 - y0))).weight;
  return weight * (x1 - x0) * (y1 - y0) / (kSub * kSub);
}

SampleSet RglBrdf::samples() const {
  SampleSet s;
  const double du = 1.0 / (grid_ - 1);
  const std::vector<double> share = azimuth_shares();
  const std::vector<Fold> copies = images();
  for (size_t slice = 0; slice < slices(); ++slice) {
    // A θi node on the horizon has no incident light: skip it.
    if (std::cos(double(theta_i_[slice % theta_i_.size()])) < 1e-6) continue;
    const double sigma_c = sigma(incidence(slice));
    for (int y = 0; y < grid_; ++y)
      for (int x = 0; x < grid_; ++x) {
        const NodeWarp n = node_warp(slice, Vec2d(x * du, y * du));
        if (!(n.wx.z() > 0)) continue;
        const double weight = node_weight(slice, y, x) * share[slice / theta_i_.size()];
        Rgb v = rgb_node(slice, y, x);
        if (jacobian_) v *= ndf_.eval(n.u_m) / (4 * sigma_c * n.wx.z());
        else v /= n.wx.z();
        for (const Fold& f : copies) s.push_back(f(n.wc), f(n.wx), v, weight, true);
      }
  }
  return s;
}

Rgb RglBrdf::albedo(const Vec3d& wi_in, int n) const {
  Rgb sum = Rgb::Zero();
  if (!(wi_in.z() > 0) || n < 1) return sum;
  const Vec3d wi = fold(wi_in)(wi_in);  // the albedo is the same at every image of wi
  const double theta_c = elevation(wi), phi_c = std::atan2(wi.y(), wi.x());
  const double params[2] = {phi_c, theta_c};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto [u_m, pdf] = vndf_.sample(Vec2d((i + 0.5) / n, (j + 0.5) / n), params);
      if (!(pdf > 0)) continue;
      const Vec3d m = spherical_direction(u2theta(u_m.x()), u2phi(u_m.y()) + (isotropic_ ? phi_c : 0.0));
      const Vec3d wo = reflect(wi, m).normalized();
      if (!(wo.z() > 0)) continue;
      const auto rho = eval(wi, wo);
      if (!rho) continue;
      // |dωo/du_m| as in node_warp(); dividing by the warp's pdf makes this a quadrature in u.
      const double jac = rgl::half_vector_jacobian(u_m.x()) * 4 * wi.dot(m);
      sum += *rho * wo.z() * jac / pdf;
    }
  return sum / (double(n) * n);
}

std::unique_ptr<MeasuredBrdf> read_rgl(const std::filesystem::path& file) { return std::make_unique<RglBrdf>(file); }

}  // namespace brdfkit
