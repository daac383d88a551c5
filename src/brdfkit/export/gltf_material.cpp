#include "brdfkit/export/gltf_material.h"

#include <tiny_gltf.h>

#include <cstring>
#include <sstream>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/models/gltf_metallic_roughness.h"

namespace brdfkit::exporter {
namespace {

using M = GltfMetallicRoughness;

tinygltf::Value to_value(const nlohmann::json& j) {
  if (j.is_object()) {
    tinygltf::Value::Object o;
    for (auto it = j.begin(); it != j.end(); ++it) o[it.key()] = to_value(it.value());
    return tinygltf::Value(std::move(o));
  }
  if (j.is_array()) {
    tinygltf::Value::Array a;
    for (const auto& x : j) a.push_back(to_value(x));
    return tinygltf::Value(std::move(a));
  }
  if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
  if (j.is_number_integer()) return tinygltf::Value(j.get<int>());
  if (j.is_number()) return tinygltf::Value(j.get<double>());
  if (j.is_string()) return tinygltf::Value(j.get<std::string>());
  return tinygltf::Value();
}

template <class T> void append_bytes(std::vector<unsigned char>& out, const std::vector<T>& v) {
  const size_t at = out.size();
  out.resize(at + v.size() * sizeof(T));
  std::memcpy(out.data() + at, v.data(), v.size() * sizeof(T));
}

// A unit UV sphere (positions = normals), 32 segments × 16 rings, indexed triangles.
void add_sphere(tinygltf::Model& g) {
  const int seg = 32, rings = 16;
  std::vector<float> pos;
  std::vector<std::uint16_t> idx;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= seg; ++s) {
      const double th = kPi * r / rings, ph = 2 * kPi * s / seg;
      pos.insert(pos.end(), {float(std::sin(th) * std::cos(ph)), float(std::cos(th)), float(std::sin(th) * std::sin(ph))});
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < seg; ++s) {
      const auto a = std::uint16_t(r * (seg + 1) + s), b = std::uint16_t(a + seg + 1);
      idx.insert(idx.end(), {a, std::uint16_t(a + 1), b, std::uint16_t(a + 1), std::uint16_t(b + 1), b});
    }
  tinygltf::Buffer buf;
  append_bytes(buf.data, pos);
  append_bytes(buf.data, idx);
  g.buffers.push_back(buf);
  const size_t pos_bytes = pos.size() * sizeof(float);
  tinygltf::BufferView vp, vi;
  vp.buffer = vi.buffer = 0;
  vp.byteOffset = 0;
  vp.byteLength = pos_bytes;
  vp.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  vi.byteOffset = pos_bytes;
  vi.byteLength = idx.size() * sizeof(std::uint16_t);
  vi.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
  g.bufferViews = {vp, vi};
  tinygltf::Accessor ap, ai;
  ap.bufferView = 0;
  ap.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  ap.count = pos.size() / 3;
  ap.type = TINYGLTF_TYPE_VEC3;
  ap.minValues = {-1, -1, -1};
  ap.maxValues = {1, 1, 1};
  ai.bufferView = 1;
  ai.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  ai.count = idx.size();
  ai.type = TINYGLTF_TYPE_SCALAR;
  g.accessors = {ap, ai};
  tinygltf::Primitive prim;
  prim.attributes["POSITION"] = 0;
  prim.attributes["NORMAL"] = 0;  // a unit sphere's normal is its position
  prim.indices = 1;
  prim.material = 0;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "sphere";
  mesh.primitives.push_back(prim);
  g.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "sphere";
  g.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  g.scenes.push_back(scene);
  g.defaultScene = 0;
}

double number(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.IsObject() || !v.Has(key)) return fallback;
  const tinygltf::Value& x = v.Get(key);
  return x.IsNumber() ? x.GetNumberAsDouble() : fallback;
}

}  // namespace

void write_gltf(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p) {
  if (brdf.model().name() != M::name())
    throw InputError("glTF export", "needs a gltf-metallic-roughness fit, got " + std::string(brdf.model().name()));
  const auto& v = brdf.values().values;
  tinygltf::Model g;
  g.asset.version = "2.0";
  g.asset.generator = "brdfkit " + p.version;
  g.asset.extras = to_value({{"brdfkit", provenance_json(p)}});
  tinygltf::Material mat;
  mat.name = "brdfkit fit";
  mat.pbrMetallicRoughness.baseColorFactor = {v[0][M::kBaseColor], v[1][M::kBaseColor], v[2][M::kBaseColor], 1.0};
  mat.pbrMetallicRoughness.metallicFactor = v[0][M::kMetallic];
  mat.pbrMetallicRoughness.roughnessFactor = v[0][M::kRoughness];
  mat.extensions["KHR_materials_ior"] = to_value({{"ior", v[0][M::kIor]}});
  const double sc = v[0][M::kSpecularColor];
  mat.extensions["KHR_materials_specular"] =
      to_value({{"specularFactor", v[0][M::kSpecular]}, {"specularColorFactor", {sc, sc, sc}}});
  mat.extras = to_value({{"brdfkit", provenance_json(p)}});
  g.materials.push_back(mat);
  g.extensionsUsed = {"KHR_materials_ior", "KHR_materials_specular"};
  add_sphere(g);
  tinygltf::TinyGLTF io;
  std::ostringstream out;
  if (!io.WriteGltfSceneToStream(&g, out, true, false))
    throw InputError(file.string(), "tinygltf could not serialize the glTF document");
  write_file_atomically(file, out.str());
}

ParamValues read_gltf_material(const std::filesystem::path& file) {
  tinygltf::Model g;
  tinygltf::TinyGLTF io;
  std::string err, warn;
  if (!io.LoadASCIIFromFile(&g, &err, &warn, file.string()))
    throw InputError(file.string(), "not a readable glTF file: " + err);
  if (g.materials.empty()) throw InputError(file.string(), "no material");
  const tinygltf::Material& m = g.materials.front();
  const auto& pbr = m.pbrMetallicRoughness;
  const ParamTable table = M::params();
  ParamValues out = ParamValues::defaults(table);
  for (int c = 0; c < 3; ++c) {
    auto& ch = out.values[size_t(c)];
    ch[M::kBaseColor] = pbr.baseColorFactor.at(size_t(c));
    ch[M::kMetallic] = pbr.metallicFactor;
    ch[M::kRoughness] = pbr.roughnessFactor;
    const auto ior = m.extensions.find("KHR_materials_ior");
    if (ior != m.extensions.end()) ch[M::kIor] = number(ior->second, "ior", 1.5);
    const auto spec = m.extensions.find("KHR_materials_specular");
    if (spec != m.extensions.end()) {
      ch[M::kSpecular] = number(spec->second, "specularFactor", 1.0);
      if (spec->second.Has("specularColorFactor")) {
        const tinygltf::Value& col = spec->second.Get("specularColorFactor");
        if (!col.IsArray() || col.ArrayLen() != 3) throw InputError(file.string(), "specularColorFactor is not 3 numbers");
        if (col.Get(0).GetNumberAsDouble() != col.Get(1).GetNumberAsDouble() ||
            col.Get(0).GetNumberAsDouble() != col.Get(2).GetNumberAsDouble())
          throw InputError(file.string(), "specularColorFactor is coloured; gltf-metallic-roughness takes a grey one");
        ch[M::kSpecularColor] = col.Get(0).GetNumberAsDouble();
      }
    }
  }
  return out;
}

}  // namespace brdfkit::exporter
