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
  check_table(path, bytes, fields, "phi_i",
              [&](const TableView& t) { t.require_each([&](float x) { return x >= -pi && x <= pi; }, "must lie in [-π, π]"); });
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

// The colour table as three channel tables of nt × grid × grid values: `rgb`, or `spectra` +
// `wavelengths` converted node by node (spectral_rgb.h).
struct ColourTable {
  std::array<std::vector<float>, 3> rgb;
  size_t negative_values = 0;  // entries < 0 (measurement noise, kept: DESIGN.md §2)
  bool spectral = false;
};
ColourTable read_colour_table(const std::vector<std::uint8_t>& bytes, const std::string& path,
                              const std::map<std::string, Field>& fields, size_t nt, size_t grid) {
  const size_t cells = grid * grid;
  ColourTable out;
  for (auto& c : out.rgb) c.resize(nt * cells);
  if (fields.count("rgb")) {
    const Field& f = required_field(path, fields, "rgb", TensorType::Float32, 5);
    if (f.shape[0] != 1 || f.shape[1] != nt || f.shape[2] != 3 || f.shape[3] != grid || f.shape[4] != grid)
      throw InputError(path, fmt::format("field 'rgb' has shape {}, expected [1,{},3,{},{}]", shape_string(f.shape), nt, grid, grid));
    const std::vector<float> v = floats(bytes, f);
    for (size_t t = 0; t < nt; ++t)
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
  if (f.shape[0] != 1 || f.shape[1] != nt || f.shape[2] != nl || f.shape[3] != grid || f.shape[4] != grid)
    throw InputError(path, fmt::format("field 'spectra' has shape {}, expected [1,{},{},{},{}]", shape_string(f.shape), nt, nl, grid, grid));
  const std::vector<double> wl(wl_f.begin(), wl_f.end());
  const Eigen::MatrixXd m = default_spectrum_to_rgb().matrix(wl);
  const std::vector<float> v = floats(bytes, f);
  Eigen::VectorXd s{Eigen::Index(nl)};
  for (size_t t = 0; t < nt; ++t)
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
  const std::vector<float> phi_i = floats(bytes, phi_f);
  const size_t nt = theta_i_.size();
  if (phi_i.size() != 1)
    throw InputError(path_, fmt::format("field 'phi_i' has {} entries: only isotropic files (one phi_i) are supported", phi_i.size()));
  if (nt < 2) throw InputError(path_, "field 'theta_i' needs at least 2 entries");
  if (jac_f.count() != 1) throw InputError(path_, "field 'jacobian' must hold one value");
  jacobian_ = bytes[jac_f.offset] != 0;

  const auto& vs = vndf_f.shape;
  const auto& ls = lum_f.shape;
  if (vs[0] != 1 || vs[1] != nt || vs[2] < 2 || vs[3] < 2)
    throw InputError(path_, fmt::format("field 'vndf' has shape {}, expected [1,{},ny,nx]", shape_string(vs), nt));
  if (ls[0] != 1 || ls[1] != nt || ls[2] != ls[3] || ls[2] < 2)
    throw InputError(path_, fmt::format("field 'luminance' has shape {}, expected [1,{},n,n]", shape_string(ls), nt));
  for (const Field* f : {&sigma_f, &ndf_f})
    if (f->shape[0] < 2 || f->shape[1] < 2) throw InputError(path_, fmt::format("fields 'sigma'/'ndf' need at least 2 x 2 entries, found {}", shape_string(f->shape)));
  check_tables(path_, bytes, fields);
  grid_ = int(ls[2]);
  ColourTable colour = read_colour_table(bytes, path_, fields, nt, size_t(grid_));
  spectral_ = colour.spectral;
  negative_values_ = colour.negative_values;

  const std::vector<std::vector<float>> params = {phi_i, theta_i_};
  ndf_ = MarginalWarp2D(floats(bytes, ndf_f).data(), int(ndf_f.shape[1]), int(ndf_f.shape[0]), {}, false);
  sigma_ = MarginalWarp2D(floats(bytes, sigma_f).data(), int(sigma_f.shape[1]), int(sigma_f.shape[0]), {}, false);
  vndf_ = MarginalWarp2D(floats(bytes, vndf_f).data(), int(vs[3]), int(vs[2]), params, true);
  luminance_raw_ = floats(bytes, lum_f);
  luminance_ = MarginalWarp2D(luminance_raw_.data(), grid_, grid_, params, false);
  for (size_t c = 0; c < 3; ++c) rgb_[c] = MarginalWarp2D(colour.rgb[c].data(), grid_, grid_, params, false);
  rgb_raw_ = std::move(colour.rgb);
}

std::string RglBrdf::dimensions() const {
  return fmt::format("{} theta_i x {}x{} {} grid (jacobian {}){}", theta_i_.size(), grid_, grid_, spectral_ ? "spectral->rgb" : "rgb",
                     jacobian_ ? 1 : 0, description_.empty() ? "" : ", \"" + description_ + "\"");
}

std::optional<Rgb> RglBrdf::eval(const Vec3d& wi, const Vec3d& wo) const { return eval_conditioned(wi, wo, true); }

namespace {
// The part of a look-up that depends on ωc alone: its angles, the interpolation weights of its
// (φc, θc) between the tables' theta_i nodes, σ(ωc). Computed once for all samples that share ωc.
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

// Shared by every evaluation (single pairs and eval_row), so they agree by construction.
std::optional<Lookup> lookup_pair(const Vec3d& wc, const Conditioning& c, const Vec3d& wx, bool cosine_of_other,
                                  bool jacobian, const MarginalWarp2D& vndf, const MarginalWarp2D& ndf) {
  if (!(wc.z() > 0) || !(wx.z() > 0)) return std::nullopt;
  const Vec3d m = (wc + wx).normalized();
  const double theta_m = elevation(m), phi_m = std::atan2(m.y(), m.x());
  // Isotropic: the half vector's azimuth is taken relative to ωc's (Dupuy & Jakob 2018 §6).
  Vec2d u_m(theta2u(theta_m), phi2u(phi_m - c.params[0]));
  u_m.y() -= std::floor(u_m.y());
  Lookup r;
  r.sample = vndf.invert(u_m, c.weights).first;
  const double cos_theta = cosine_of_other ? wx.z() : wc.z();
  // DESIGN.md §2: ρ = table · D(h) / (4 σ(ωc) cos θx); with jacobian = 0 the table holds ρ·cos θx.
  r.factor = jacobian ? ndf.eval(u_m) / (4 * c.sigma * cos_theta) : 1 / cos_theta;
  return r;
}
}  // namespace

std::optional<Rgb> RglBrdf::eval_conditioned(const Vec3d& wc, const Vec3d& wx, bool cosine_of_other) const {
  if (!(wc.z() > 0) || !(wx.z() > 0)) return std::nullopt;
  const Conditioning c = condition_on(wc, vndf_, sigma_);
  const auto l = lookup_pair(wc, c, wx, cosine_of_other, jacobian_, vndf_, ndf_);
  if (!l) return std::nullopt;
  Rgb v;
  for (int k = 0; k < 3; ++k) v[k] = rgb_[size_t(k)].eval(l->sample, c.weights);
  return Rgb(v * l->factor);
}

void RglBrdf::eval_row(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const {
  out.assign(wo.size(), std::nullopt);
  if (!(wi.z() > 0)) return;
  const Conditioning c = condition_on(wi, vndf_, sigma_);
  for (size_t k = 0; k < wo.size(); ++k) {
    const auto l = lookup_pair(wi, c, wo[k], true, jacobian_, vndf_, ndf_);
    if (!l) continue;
    const MarginalWarp2D::Patch patch = rgb_[0].locate(l->sample);  // the colour tables share their grid
    Rgb v;
    for (int ch = 0; ch < 3; ++ch) v[ch] = rgb_[size_t(ch)].eval(patch, c.weights);
    out[k] = Rgb(v * l->factor);
  }
}

std::optional<double> RglBrdf::eval_luminance(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0) || !(wo.z() > 0)) return std::nullopt;
  const Conditioning c = condition_on(wi, vndf_, sigma_);
  const auto l = lookup_pair(wi, c, wo, true, jacobian_, vndf_, ndf_);
  if (!l) return std::nullopt;
  return luminance_.eval(l->sample, c.weights) * l->factor;
}

std::optional<Vec2d> RglBrdf::table_coordinates(const Vec3d& wc, const Vec3d& wx) const {
  if (!(wc.z() > 0) || !(wx.z() > 0)) return std::nullopt;
  const auto l = lookup_pair(wc, condition_on(wc, vndf_, sigma_), wx, true, jacobian_, vndf_, ndf_);
  if (!l) return std::nullopt;
  return l->sample;
}

Rgb RglBrdf::rgb_node(size_t t, int y, int x) const {
  const size_t i = t * size_t(grid_) * size_t(grid_) + size_t(y) * size_t(grid_) + size_t(x);
  return Rgb(rgb_raw_[0][i], rgb_raw_[1][i], rgb_raw_[2][i]);
}

double RglBrdf::ndf(const Vec3d& m) const {
  return ndf_.eval(Vec2d(theta2u(elevation(m)), phi2u(std::atan2(m.y(), m.x()))));
}

double RglBrdf::sigma(const Vec3d& w) const {
  return sigma_.eval(Vec2d(theta2u(elevation(w)), phi2u(std::atan2(w.y(), w.x()))));
}

double RglBrdf::luminance_node(size_t t, int y, int x) const {
  return luminance_raw_[t * size_t(grid_) * size_t(grid_) + size_t(y) * size_t(grid_) + size_t(x)];
}


std::optional<std::pair<Vec3d, Vec3d>> RglBrdf::node_directions(size_t t, int y, int x) const {
  const Vec3d wc = spherical_direction(double(theta_i_[t]), 0.0);
  const double params[2] = {0.0, theta_i_[t]};
  const Vec2d u_m = vndf_.sample(Vec2d(double(x) / (grid_ - 1), double(y) / (grid_ - 1)), params).first;
  const Vec3d m = spherical_direction(u2theta(u_m.x()), u2phi(u_m.y()));
  const Vec3d wx = reflect(wc, m);
  if (!(wx.z() > 0)) return std::nullopt;
  return std::pair{wc, wx.normalized()};
}

SampleSet RglBrdf::samples() const {
  SampleSet s;
  const double du = 1.0 / (grid_ - 1);
  constexpr int kSub = 4;  // sub-samples per cell side for the cell's solid angle
  for (size_t t = 0; t < theta_i_.size(); ++t) {
    // A θi node on the horizon has no incident light: skip it.
    if (std::cos(double(theta_i_[t])) < 1e-6) continue;
    const Vec3d wc = spherical_direction(double(theta_i_[t]), 0.0);
    const double params[2] = {0.0, theta_i_[t]};
    const double sigma_c = sigma_.eval(Vec2d(theta2u(theta_i_[t]), phi2u(0.0)));
    // Where the warp sends a unit-square point, and |dωx/du| there: Dupuy & Jakob 2018 §5
    // (Mitsuba 3 `measured`): dωm = 2π² u_m,x sin θm du_m, dωx = 4 (ωc·m) dωm, du_m = pdf du.
    auto warp = [&](const Vec2d& u) {
      const auto [u_m, pdf] = vndf_.sample(u, params);
      const double theta_m = u2theta(u_m.x());
      const Vec3d m = spherical_direction(theta_m, u2phi(u_m.y()));
      const Vec3d wx = reflect(wc, m).normalized();
      const double jac = rgl::half_vector_jacobian(u_m.x()) * 4 * wc.dot(m);
      return std::tuple{u_m, wx, pdf > 0 && wx.z() > 0 ? jac / pdf : 0.0};
    };
    for (int y = 0; y < grid_; ++y)
      for (int x = 0; x < grid_; ++x) {
        const auto [u_m, wx, unused] = warp(Vec2d(x * du, y * du));
        if (!(wx.z() > 0)) continue;
        // Weight: the solid angle of wo over the node's cell [x ± ½, y ± ½] ∩ [0,1]² of the unit
        // square, by a 4 × 4 midpoint rule. (Trapezoid weights at the nodes would give the x = 0
        // column, h = n, no weight: the specular peak of glossy files would be lost.)
        const double x0 = std::max(0.0, (x - 0.5) * du), x1 = std::min(1.0, (x + 0.5) * du);
        const double y0 = std::max(0.0, (y - 0.5) * du), y1 = std::min(1.0, (y + 0.5) * du);
        double weight = 0;
        for (int j = 0; j < kSub; ++j)
          for (int i = 0; i < kSub; ++i)
            weight += std::get<2>(warp(Vec2d(x0 + (i + 0.5) / kSub * (x1 - x0), y0 + (j + 0.5) / kSub * (y1 - y0))));
        weight *= (x1 - x0) * (y1 - y0) / (kSub * kSub);
        Rgb v = rgb_node(t, y, x);
        if (jacobian_) v *= ndf_.eval(u_m) / (4 * sigma_c * wx.z());
        else v /= wx.z();
        s.push_back(wc, wx, v, weight, true);
      }
  }
  return s;
}

Rgb RglBrdf::albedo(const Vec3d& wi, int n) const {
  Rgb sum = Rgb::Zero();
  if (!(wi.z() > 0) || n < 1) return sum;
  const double theta_c = elevation(wi), phi_c = std::atan2(wi.y(), wi.x());
  const double params[2] = {phi_c, theta_c};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto [u_m, pdf] = vndf_.sample(Vec2d((i + 0.5) / n, (j + 0.5) / n), params);
      if (!(pdf > 0)) continue;
      const double theta_m = u2theta(u_m.x());
      const Vec3d m = spherical_direction(theta_m, u2phi(u_m.y()) + phi_c);
      const Vec3d wo = reflect(wi, m).normalized();
      if (!(wo.z() > 0)) continue;
      const auto rho = eval(wi, wo);
      if (!rho) continue;
      // |dωo/du_m| as in samples(); dividing by the warp's pdf makes this a quadrature in u.
      const double jac = rgl::half_vector_jacobian(u_m.x()) * 4 * wi.dot(m);
      sum += *rho * wo.z() * jac / pdf;
    }
  return sum / (double(n) * n);
}

std::unique_ptr<MeasuredBrdf> read_rgl(const std::filesystem::path& file) { return std::make_unique<RglBrdf>(file); }

}  // namespace brdfkit
