#include "brdfkit/export/mitsuba_scene.h"

#include <fmt/format.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/export/scene_files.h"

namespace brdfkit::exporter {
namespace {

std::string float_property(const char* name, double v) {
  return fmt::format("        <float name=\"{}\" value=\"{}\"/>\n", name, num(v));
}
std::string rgb_property(const char* name, const ParamValues& v, int param) {
  return fmt::format("        <rgb name=\"{}\" value=\"{}\"/>\n", name, rgb(v.values, param, ", "));
}

// The <bsdf> element: every parameter under the renderer's own name (models/mitsuba_*.h).
std::string bsdf_element(const Brdf& brdf) {
  const std::string_view model = brdf.model().name();
  const ParamValues& v = brdf.values();
  const ParamTable& t = brdf.model().params();
  std::string body;
  if (model == "mitsuba-principled") {
    body += "    <bsdf type=\"principled\" id=\"brdfkit_fit\">\n";
    body += "        <!-- spec_tint, sheen_tint, anisotropic and spec_trans stay at their default 0 -->\n";
    body += rgb_property("base_color", v, find_param(t, "base_color"));
    for (const char* name : {"roughness", "metallic", "specular", "sheen", "clearcoat", "clearcoat_gloss", "flatness"})
      body += float_property(name, v.values[0][size_t(find_param(t, name))]);
  } else if (model == "mitsuba-roughconductor-beckmann" || model == "mitsuba-roughconductor-ggx") {
    body += "    <bsdf type=\"roughconductor\" id=\"brdfkit_fit\">\n";
    body += fmt::format("        <string name=\"distribution\" value=\"{}\"/>\n",
                        model.ends_with("ggx") ? "ggx" : "beckmann");
    body += float_property("alpha", v.values[0][size_t(find_param(t, "alpha"))]);
    for (const char* name : {"eta", "k", "specular_reflectance"}) body += rgb_property(name, v, find_param(t, name));
  } else {
    throw InputError("Mitsuba 3 export", "needs a mitsuba-principled or mitsuba-roughconductor-* fit, got " +
                                             std::string(model));
  }
  return body + "    </bsdf>\n";
}

std::string scene_xml(const std::filesystem::path& material) {
  const Vec3d l = kSceneLight;
  return fmt::format(R"(<scene version="3.0.0">
    <!-- brdfkit's point-light sphere: unit sphere at the origin, camera on +z, world y up -->
    <include filename="{}"/>
    <integrator type="direct"/>
    <sensor type="perspective">
        <float name="fov" value="{}"/>
        <transform name="to_world">
            <lookat origin="0, 0, {}" target="0, 0, 0" up="0, 1, 0"/>
        </transform>
        <sampler type="independent">
            <integer name="sample_count" value="64"/>
        </sampler>
        <film type="hdrfilm">
            <integer name="width" value="{}"/>
            <integer name="height" value="{}"/>
            <rfilter type="box"/>
        </film>
    </sensor>
    <emitter type="directional">
        <vector name="direction" value="{}, {}, {}"/>
        <rgb name="irradiance" value="1, 1, 1"/>
    </emitter>
    <shape type="sphere">
        <ref id="brdfkit_fit"/>
    </shape>
</scene>
)",
                     material.filename().string(), num(kSceneFovDeg), num(kSceneCameraZ), kSceneResolution,
                     kSceneResolution, num(-l.x()), num(-l.y()), num(-l.z()));
}

}  // namespace

std::vector<std::filesystem::path> write_mitsuba(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p) {
  const std::string material = "<scene version=\"3.0.0\">\n    <!--\n" + comment_block(p, "    ") +
                               "    Render with an RGB variant (scalar_rgb, llvm_ad_rgb): values are per RGB channel.\n"
                               "    -->\n" +
                               bsdf_element(brdf) + "</scene>\n";
  const std::filesystem::path scene = scene_path(file);
  write_file_atomically(file, material);
  write_file_atomically(scene, scene_xml(file));
  return {file, scene};
}

}  // namespace brdfkit::exporter
