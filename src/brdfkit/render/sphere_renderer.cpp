#include "brdfkit/render/sphere_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <mutex>

#include "brdfkit/core/error.h"
#include "brdfkit/core/warp.h"

namespace brdfkit::render {
namespace {

// SplitMix64 (Steele et al. 2014) turns (seed, pixel) into a well-mixed stream seed.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// SplitMix64 as the generator too (it passes BigCrush; Steele et al. 2014): a pixel's stream is
// its seed's Weyl sequence through the mixer, so starting a stream costs nothing.
struct Sampler {
  std::uint64_t state;
  double next() { return double(mix(state += 0x9e3779b97f4a7c15ull) >> 11) * 0x1p-53; }
  Vec2d next2() {
    const double a = next();
    return Vec2d(a, next());
  }
};

// Power heuristic, β = 2 (Veach 1997 Eq. 9.13), for the strategy of density a against b.
double power_weight(double a, double b) { return a * a / (a * a + b * b); }

// The environment's own strategy: its map's distribution, or for a constant environment the
// cosine-weighted hemisphere around n (it samples L cos θi exactly). Local direction and density.
struct LightDraw {
  Vec3d wi;
  double pdf;
};
LightDraw draw_light(const EnvironmentMap& env, const SphereHit& hit, const Vec2d& u) {
  if (env.is_constant()) {
    const Vec3d wi = square_to_cosine_hemisphere(u);
    return {wi, cosine_hemisphere_pdf(wi)};
  }
  double pdf = 0;
  const Vec3d d = env.sample(u, &pdf);
  return {hit.to_local_dir(d), pdf};
}
// Radiance towards wi and the environment strategy's density there.
EnvironmentMap::Texel light_at(const EnvironmentMap& env, const SphereHit& hit, const Vec3d& wi) {
  EnvironmentMap::Texel t = env.lookup(hit.to_world(wi));
  if (env.is_constant()) t.pdf = cosine_hemisphere_pdf(wi);
  return t;
}

// One sample of the environment integral at a hit: an environment draw and a reflector draw,
// weighted by the power heuristic.
Rgb environment_sample(const Reflector& r, const EnvironmentMap& env, const SphereHit& hit, Sampler& s) {
  Rgb sum = Rgb::Zero();
  const Vec3d& wo = hit.wo_local;
  if (env.is_constant() || env.samplable()) {
    const LightDraw l = draw_light(env, hit, s.next2());
    if (l.wi.z() > 0 && l.pdf > 0)
      sum += r.eval(l.wi, wo) * env.radiance(hit.to_world(l.wi)) *
             (l.wi.z() * power_weight(l.pdf, r.pdf(wo, l.wi)) / l.pdf);
  } else {
    s.next2();  // keep the stream's layout whatever the map
  }
  const Vec2d u = s.next2();
  const std::optional<Vec3d> wi = r.sample(wo, u, s.next());
  if (wi && wi->z() > 0) {
    const double pb = r.pdf(wo, *wi);
    if (pb > 0) {
      const EnvironmentMap::Texel t = light_at(env, hit, *wi);
      sum += r.eval(*wi, wo) * t.radiance * (wi->z() * power_weight(pb, t.pdf) / pb);
    }
  }
  return sum;
}

Rgb point_lights(const Reflector& r, const std::vector<PointLight>& lights, const SphereHit& hit) {
  Rgb sum = Rgb::Zero();
  for (const PointLight& l : lights) {
    const Vec3d wi = hit.to_local_dir(l.direction);
    if (wi.z() > 0) sum += l.intensity * r.eval(wi, hit.wo_local) * wi.z();
  }
  return sum;
}

struct PixelEstimate {
  Rgb mean = Rgb::Zero(), standard_error = Rgb::Zero();
  std::size_t dropped = 0;
  bool covered = false;
};

PixelEstimate render_pixel(const Reflector& r, const Scene& scene, const Camera& cam, const RenderSettings& st, int x,
                           int y) {
  Sampler s{mix(st.seed ^ mix(std::uint64_t(y) * std::uint64_t(st.width) + std::uint64_t(x)))};
  PixelEstimate p;
  Rgb mean = Rgb::Zero(), m2 = Rgb::Zero();  // Welford's running moments
  int n = 0;
  for (int k = 0; k < st.spp; ++k) {
    const Vec2d j = st.jitter ? s.next2() : Vec2d(0.5, 0.5);
    const std::optional<SphereHit> hit = cam.hit(x + j.x(), y + j.y());
    if (!hit) continue;  // a jittered ray past the silhouette: the pixel's coverage is partial
    Rgb v = point_lights(r, scene.lights, *hit);
    if (scene.environment) v += environment_sample(r, *scene.environment, *hit, s);
    if (!v.allFinite()) {
      ++p.dropped;
      continue;
    }
    ++n;
    const Rgb delta = v - mean;
    mean += delta / n;
    m2 += delta * (v - mean);
  }
  // A pixel counts as the object's when at least half its samples hit the sphere.
  p.covered = n > 0 && 2 * (n + int(p.dropped)) >= st.spp;
  p.mean = mean * (double(n) / st.spp);
  if (n > 1) p.standard_error = (m2 / (n - 1) / n).sqrt();
  return p;
}

}  // namespace

RenderResult render_sphere(const Reflector& reflector, const Scene& scene, const RenderSettings& st) {
  if (st.width < 1 || st.height < 1 || st.spp < 1) throw InputError("render", "size and samples per pixel must be >= 1");
  const Camera cam(st.width, st.height, st.camera_distance);
  RenderResult out{Image(st.width, st.height), Image(st.width, st.height), 0};
  std::atomic<std::size_t> dropped{0};
  std::atomic<int> rows_done{0};
  std::mutex progress_mutex;
  std::atomic<int> reported{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, st.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < st.width; ++x) {
        const PixelEstimate p = render_pixel(reflector, scene, cam, st, x, y);
        const size_t k = size_t(y) * size_t(st.width) + size_t(x);
        out.radiance.pixels[k] = p.mean;
        out.standard_error.pixels[k] = p.standard_error;
        out.radiance.covered[k] = out.standard_error.covered[k] = p.covered;
        dropped += p.dropped;
      }
      const int done = ++rows_done;
      if (st.progress && done * 20 / st.height > reported.load()) {
        std::lock_guard lock(progress_mutex);
        if (done * 20 / st.height > reported.load()) {
          reported = done * 20 / st.height;
          st.progress(double(done) / st.height);
        }
      }
    }
  });
  out.dropped = dropped;
  return out;
}

}  // namespace brdfkit::render
