#include "brdfkit/render/reflector.h"

#include "brdfkit/core/warp.h"

namespace brdfkit::render {
namespace {

class ModelReflector final : public Reflector {
 public:
  explicit ModelReflector(const Brdf& b) : brdf_(b) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo) const override { return brdf_.eval(wi, wo); }
  std::optional<Vec3d> sample(const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return brdf_.sample(wo, u, u_lobe);
  }
  double pdf(const Vec3d& wo, const Vec3d& wi) const override { return brdf_.pdf(wo, wi); }

 private:
  Brdf brdf_;
};

class MeasuredReflector final : public Reflector {
 public:
  MeasuredReflector(const MeasuredBrdf& data, const std::optional<Brdf>& proxy) : data_(data), proxy_(proxy) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo) const override {
    const std::optional<Rgb> v = data_.eval(wo, wi);  // conditioned on the view direction (reflector.h)
    return v ? Rgb(v->cwiseMax(0.0)) : Rgb(Rgb::Zero());
  }
  std::optional<Vec3d> sample(const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    if (!proxy_ || u_lobe >= kProxyShare) return square_to_cosine_hemisphere(u);
    return proxy_->sample(wo, u, u_lobe / kProxyShare);
  }
  double pdf(const Vec3d& wo, const Vec3d& wi) const override {
    const double cosine = cosine_hemisphere_pdf(wi);
    return proxy_ ? kProxyShare * proxy_->pdf(wo, wi) + (1 - kProxyShare) * cosine : cosine;
  }

 private:
  static constexpr double kProxyShare = 0.75;
  const MeasuredBrdf& data_;
  std::optional<Brdf> proxy_;
};

}  // namespace

std::unique_ptr<Reflector> model_reflector(const Brdf& brdf) { return std::make_unique<ModelReflector>(brdf); }

std::unique_ptr<Reflector> measured_reflector(const MeasuredBrdf& data, const std::optional<Brdf>& proxy) {
  return std::make_unique<MeasuredReflector>(data, proxy);
}

}  // namespace brdfkit::render
