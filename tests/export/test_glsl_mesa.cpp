// The exported GLSL runs: a fragment shader built around it draws brdfkit's point-light sphere
// (DESIGN.md §13: unit sphere at the origin, pinhole camera on +z, world y up, tangent =
// normalize(y × n), one distant light of intensity 1) on Mesa's software rasterizer (OSMesa,
// llvmpipe) into a float target, and the image is compared with the same sphere evaluated in
// double from the Brdf: ρ(l, v) cosθl per pixel. Float precision: max relative difference ≤ 1e-3
// over the pixels with n·v ≥ 0.1 and n·l ≥ 0.05 (the silhouette and the terminator, where a float
// normal moves the cosines most, are left out). A 1 % change of one fitted value must fail it.
#include <gtest/gtest.h>

#ifdef BRDFKIT_HAVE_OSMESA
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#endif

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/export/glsl_function.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

constexpr int kSize = 96;
const Vec3d kLight = Vec3d(0.5, 0.5, 0.70710678118654752);
constexpr double kFovDeg = 35.0, kCameraZ = 4.0;

const char* kFragmentMain = R"(
out vec4 colour;
const vec3 LIGHT = vec3(0.5, 0.5, 0.70710678118654752);
void main() {
  float t = tan(radians(35.0) / 2.0);
  vec2 p = gl_FragCoord.xy / 96.0 * 2.0 - 1.0;
  vec3 d = normalize(vec3(p.x * t, p.y * t, -1.0)), o = vec3(0.0, 0.0, 4.0);
  float b = dot(o, d), disc = b * b - (dot(o, o) - 1.0);
  if (disc < 0.0) { colour = vec4(0.0); return; }
  vec3 n = normalize(o + (-b - sqrt(disc)) * d);
  vec3 tg = normalize(cross(vec3(0.0, 1.0, 0.0), n)), bt = cross(n, tg);
  vec3 wi = vec3(dot(LIGHT, tg), dot(LIGHT, bt), dot(LIGHT, n)), wo = vec3(dot(-d, tg), dot(-d, bt), dot(-d, n));
  colour = vec4(wi.z > 0.0 ? brdfkit_brdf(wi, wo) * wi.z : vec3(0.0), 1.0);
}
)";

struct Pixel {
  bool compared = false;
  Rgb value = Rgb::Zero();
};

// The reference image: the same rays in double, ρ from the Brdf.
std::vector<Pixel> reference_image(const Brdf& brdf) {
  std::vector<Pixel> img(kSize * kSize);
  const double t = std::tan(kFovDeg * kPi / 360);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Vec3d d = Vec3d(((x + 0.5) / kSize * 2 - 1) * t, ((y + 0.5) / kSize * 2 - 1) * t, -1).normalized();
      const Vec3d o(0, 0, kCameraZ);
      const double b = o.dot(d), disc = b * b - (o.dot(o) - 1);
      if (disc < 0) continue;
      const Vec3d n = (o + (-b - std::sqrt(disc)) * d).normalized();
      const Vec3d tg = Vec3d(0, 1, 0).cross(n).normalized(), bt = n.cross(tg);
      const Vec3d wi(kLight.dot(tg), kLight.dot(bt), kLight.dot(n)), wo((-d).dot(tg), (-d).dot(bt), (-d).dot(n));
      Pixel& px = img[size_t(y * kSize + x)];
      px.compared = wo.z() >= 0.1 && wi.z() >= 0.05;
      if (wi.z() > 0) px.value = brdf.eval(wi, wo) * wi.z();
    }
  return img;
}

#ifdef BRDFKIT_HAVE_OSMESA
GLuint compile(GLenum type, const std::string& src) {
  const GLuint s = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(s, 1, &p, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    ADD_FAILURE() << "shader does not compile: " << log;
  }
  return s;
}

// The sphere drawn by the GLSL of `brdf` on OSMesa; nullopt (with a printed reason) where no
// OpenGL 3.3 core context can be made.
std::optional<std::vector<float>> render(const Brdf& brdf) {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION,
                         3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) return std::nullopt;
  std::vector<unsigned char> window(kSize * kSize * 4);
  if (!OSMesaMakeCurrent(ctx, window.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    OSMesaDestroyContext(ctx);
    return std::nullopt;
  }
  GLuint fbo, tex, vao;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kSize, kSize, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  const std::string vs = "#version 330 core\nvoid main() { vec2 p = vec2(float((gl_VertexID & 1) << 2), "
                         "float((gl_VertexID & 2) << 1)) - 1.0; gl_Position = vec4(p, 0.0, 1.0); }\n";
  const std::string fs = "#version 330 core\n" + exporter::glsl_constants(brdf) + exporter::glsl_functions(brdf.model()) +
                         kFragmentMain;
  const GLuint prog = glCreateProgram();
  glAttachShader(prog, compile(GL_VERTEX_SHADER, vs));
  glAttachShader(prog, compile(GL_FRAGMENT_SHADER, fs));
  glLinkProgram(prog);
  glUseProgram(prog);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glViewport(0, 0, kSize, kSize);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> out(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, out.data());
  OSMesaDestroyContext(ctx);
  return out;
}
#endif

// Largest relative difference over the compared pixels (channels whose reference is below 1e-4 of
// the image's largest value are judged against that floor).
double max_relative_difference(const std::vector<float>& gl, const std::vector<Pixel>& ref) {
  double peak = 0, worst = 0;
  for (const Pixel& p : ref) peak = std::max(peak, p.value.maxCoeff());
  for (size_t k = 0; k < ref.size(); ++k) {
    if (!ref[k].compared) continue;
    EXPECT_EQ(gl[4 * k + 3], 1.0f) << "pixel " << k << " missed the sphere";
    for (int c = 0; c < 3; ++c) {
      const double r = ref[k].value[c];
      worst = std::max(worst, std::abs(double(gl[4 * k + size_t(c)]) - r) / std::max(r, 1e-4 * peak));
    }
  }
  return worst;
}

Brdf brdf_of(const char* model, const std::vector<std::pair<std::string, std::vector<double>>>& values) {
  const Model& m = model_by_name(model);
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, x] : values)
    for (int c = 0; c < 3; ++c) v.set(m.params(), name, x.size() == 3 ? x[size_t(c)] : x[0], x.size() == 3 ? c : -1);
  return Brdf(m, v);
}

TEST(GlslMesa, SphereMatchesTheBrdfAndAPerturbationFails) {
#ifndef BRDFKIT_HAVE_OSMESA
  GTEST_SKIP() << "built without OSMesa (Debian libosmesa6-dev): GLSL not run";
#else
  const std::vector<std::pair<const char*, Brdf>> fits = {
      {"gltf", brdf_of("gltf-metallic-roughness",
                       {{"base_color", {0.7, 0.4, 0.2}}, {"metallic", {0.3}}, {"roughness", {0.45}}})},
      {"mitsuba", brdf_of("mitsuba-principled", {{"base_color", {0.3, 0.5, 0.8}}, {"roughness", {0.4}},
                                                  {"specular", {0.6}}, {"clearcoat", {0.5}}, {"sheen", {0.3}}})},
      {"cook-torrance-ggx", brdf_of("cook-torrance-ggx", {{"kd", {0.4, 0.3, 0.2}}, {"ks", {0.8}}, {"alpha", {0.3}}})}};
  for (const auto& [label, brdf] : fits) {
    const auto gl = render(brdf);
    if (!gl) GTEST_SKIP() << "OSMesa gave no OpenGL 3.3 core context";
    const auto ref = reference_image(brdf);
    int compared = 0;
    for (const Pixel& p : ref) compared += p.compared;
    const double d = max_relative_difference(*gl, ref);
    std::printf("%-18s GLSL on OSMesa vs Brdf: %d pixels, max relative difference %.2e\n", label, compared, d);
    EXPECT_GT(compared, 3000);
    EXPECT_LE(d, 1e-3) << label;
    // The same comparison with one fitted value off by 1 %.
    ParamValues off = brdf.values();
    const int shape = [&] {
      for (size_t i = 0; i < brdf.model().params().size(); ++i)
        if (brdf.model().params()[i].scope == Scope::Shared) return int(i);
      return 0;
    }();
    for (auto& ch : off.values) ch[size_t(shape)] *= 1.01;
    const double dp = max_relative_difference(*render(Brdf(brdf.model(), off)), ref);
    std::printf("%-18s %s x 1.01: max relative difference %.2e\n", label, brdf.model().params()[size_t(shape)].name.c_str(), dp);
    EXPECT_GT(dp, 1e-3) << label;
  }
#endif
}

}  // namespace
}  // namespace brdfkit
