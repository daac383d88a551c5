#include "brdfkit/measured/merl_brdf.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <vector>

#include "brdfkit/measured/merl_row_cells.h"

namespace brdfkit {

double merl_cell_weight(const merl::Cell& c) {
  using namespace merl;
  auto theta_h = [](int i) {
    const double u = double(i) / kResThetaH;
    return u * u * (kPi / 2);  // θh axis of DESIGN.md §2, at the cell's lower and upper edges
  };
  auto sin2_theta_d = [](int j) {
    const double s = std::sin(double(j) / kResThetaD * (kPi / 2));
    return s * s;
  };
  const double d_cos_h = std::cos(theta_h(c.theta_h)) - std::cos(theta_h(c.theta_h + 1));
  const double d_sin2_d = sin2_theta_d(c.theta_d + 1) - sin2_theta_d(c.theta_d);
  return 2 * kPi * d_cos_h * 4 * 0.5 * d_sin2_d * 2 * (kPi / kResPhiD);
}

void MerlBrdf::eval_row(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const {
  thread_local std::vector<size_t> cells;  // rows come from parallel loops: each thread keeps its buffer
  merl::row_cells(wi, wo, cells);
  out.resize(wo.size());
  for (size_t k = 0; k < wo.size(); ++k)
    if (cells[k] != merl::kNoCell && table_.valid(cells[k])) out[k] = table_.value(cells[k]);
    else out[k] = std::nullopt;
}

SampleSet MerlBrdf::samples() const {
  // One chunk per θh row in parallel (directions cost trigonometry), joined in row order so the
  // result is the same on any number of threads.
  std::vector<SampleSet> rows(merl::kResThetaH);
  tbb::parallel_for(0, merl::kResThetaH, [&](int ih) {
    SampleSet& row = rows[size_t(ih)];
    const size_t begin = merl::cell_offset({ih, 0, 0}), end = begin + size_t(merl::kResThetaD) * merl::kResPhiD;
    for (size_t k = begin; k < end; ++k) {
      if (!table_.valid(k)) continue;
      const merl::Cell c = merl::cell_at(k);
      Vec3d wi, wo;
      if (!merl::cell_directions(c, wi, wo)) continue;
      row.push_back(wi, wo, table_.value(k), merl_cell_weight(c), true);
    }
  });
  SampleSet s;
  size_t n = 0;
  for (const SampleSet& row : rows) n += row.size();
  s.reserve(n);
  for (const SampleSet& row : rows) {
    auto append = [](std::vector<double>& dst, const std::vector<double>& src) {
      dst.insert(dst.end(), src.begin(), src.end());
    };
    append(s.wi_x, row.wi_x), append(s.wi_y, row.wi_y), append(s.wi_z, row.wi_z);
    append(s.wo_x, row.wo_x), append(s.wo_y, row.wo_y), append(s.wo_z, row.wo_z);
    for (size_t c = 0; c < 3; ++c) append(s.rgb[c], row.rgb[c]);
    append(s.weight, row.weight);
    s.valid.insert(s.valid.end(), row.valid.begin(), row.valid.end());
  }
  return s;
}

std::unique_ptr<MerlBrdf> read_merl(const std::filesystem::path& file) {
  return std::make_unique<MerlBrdf>(merl::read(file), file.string());
}

}  // namespace brdfkit
