// glTF 2.0, .gltf and .glb (docs/scenes.md). tinygltf skips what it cannot use, so the file is
// first checked structurally (GLB header, JSON syntax and property types, accessors, indices,
// the node hierarchy) and every problem is reported with its place. Debian's shared library
// (built with Debian's nlohmann-json and stb) holds the loader's implementation.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "io/internal/loaders.h"
#include "io/internal/mesh_builder.h"
#include "io/internal/text.h"

namespace zb {

using namespace text;

namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxJsonDepth = 64;  // arrays and objects in glTF JSON

// ---- glTF and GLB ----------------------------------------------------------------------------

uint32_t read_u32(const std::string& data, size_t at) {
  uint32_t v = 0;
  std::memcpy(&v, data.data() + at, 4);
  return v;  // GLB is little-endian, as is every target zblend builds for
}

// The JSON chunk of a GLB file, after checking the header and chunk lengths.
std::string glb_json_chunk(const std::string& path, const std::string& data) {
  if (data.size() < 12) fail(path, "byte 0", fmt::format("GLB header needs 12 bytes, file has {}", data.size()));
  if (data.compare(0, 4, "glTF") != 0) fail(path, "byte 0", "not a GLB file (magic is not 'glTF')");
  if (read_u32(data, 4) != 2) fail(path, "byte 4", fmt::format("GLB version {}, expected 2", read_u32(data, 4)));
  const uint32_t length = read_u32(data, 8);
  if (length != data.size())
    fail(path, "byte 8", fmt::format("GLB length {} but the file has {} bytes (truncated?)", length, data.size()));
  size_t at = 12;
  std::string json;
  for (int chunk = 0; at < data.size(); ++chunk) {
    if (data.size() - at < 8) fail(path, fmt::format("byte {}", at), "truncated chunk header");
    const uint32_t clen = read_u32(data, at), type = read_u32(data, at + 4);
    if (clen > data.size() - at - 8)
      fail(path, fmt::format("byte {}", at),
           fmt::format("chunk {} of {} bytes runs past the end of the file", chunk, clen));
    if (chunk == 0) {
      if (type != 0x4E4F534Au) fail(path, fmt::format("byte {}", at + 4), "first chunk is not JSON");
      json = data.substr(at + 8, clen);
    }
    at += 8 + clen;
  }
  if (at == 12) fail(path, "byte 12", "no JSON chunk");
  return json;
}

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;  // textures are not sampled (docs/scenes.md)
}

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

// An accessor's elements, bounds-checked against its buffer view and buffer.
struct AccessorView {
  const unsigned char* data = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int component = 0;
};

class GltfReader {
 public:
  GltfReader(const std::string& path, const tinygltf::Model& model) : path_(path), model_(model) {}

  Scene read() {
    scene_.name = path_;
    for (size_t i = 0; i < model_.materials.size(); ++i) add_material(i);
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (static_cast<size_t>(s) >= model_.scenes.size())
        fail(path_, "scene", fmt::format("default scene {} does not exist", s));
      roots = model_.scenes[s].nodes;
    } else {
      std::vector<bool> child(model_.nodes.size(), false);
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && static_cast<size_t>(c) < child.size()) child[c] = true;
      for (size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    for (int r : roots) visit(r);
    warn_textures();
    if (default_used_) scene_.materials.push_back(Material{"default", {255, 255, 255, 255}});
    scene_.description = fmt::format("glTF file, {} nodes, {} meshes, {} materials", model_.nodes.size(),
                                      model_.meshes.size(), model_.materials.size());
    if (ignored_) scene_.description += fmt::format("; {} point or line primitives ignored", ignored_);
    if (masked_) scene_.description += fmt::format("; {} MASK primitives below alphaCutoff dropped", masked_);
    return std::move(scene_);
  }

 private:
  void add_material(size_t i) {
    const tinygltf::Material& m = model_.materials[i];
    const std::string place = fmt::format("materials[{}]", i);
    std::vector<double> f = m.pbrMetallicRoughness.baseColorFactor;
    if (f.empty()) f = {1, 1, 1, 1};
    if (f.size() != 4) fail(path_, place, "baseColorFactor needs 4 numbers");
    for (double v : f)
      if (!std::isfinite(v) || v < 0 || v > 1) fail(path_, place, fmt::format("baseColorFactor {} is outside 0 to 1", v));
    Material mat;
    mat.name = m.name.empty() ? fmt::format("material {}", i) : m.name;
    mat.color = {to_unorm8(f[0]), to_unorm8(f[1]), to_unorm8(f[2]), to_unorm8(f[3])};
    bool drop = false;
    if (m.alphaMode.empty() || m.alphaMode == "OPAQUE") {
      mat.color.a = 255;
    } else if (m.alphaMode == "MASK") {
      // Without textures every fragment has the factor's alpha: all kept (opaque) or all discarded.
      drop = !(f[3] >= m.alphaCutoff);
      mat.color.a = 255;
    } else if (m.alphaMode != "BLEND") {
      fail(path_, place, fmt::format("unknown alphaMode '{}'", m.alphaMode));
    }
    scene_.materials.push_back(mat);
    dropped_.push_back(drop);
  }

  // Textures are not sampled: each drawn material with a base colour texture is named.
  void warn_textures() {
    warn_ignored_textures(scene_, [&](uint32_t m) {
      return m < model_.materials.size() &&
             model_.materials[m].pbrMetallicRoughness.baseColorTexture.index >= 0;
    });
  }

  glm::mat4 local_matrix(const tinygltf::Node& n, const std::string& place) const {
    glm::mat4 m(1.0f);
    if (!n.matrix.empty()) {
      if (n.matrix.size() != 16) fail(path_, place, "matrix needs 16 numbers");
      for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);  // column-major
    } else {
      glm::vec3 t(0.0f), s(1.0f);
      glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
      if (n.translation.size() == 3) t = {n.translation[0], n.translation[1], n.translation[2]};
      if (n.scale.size() == 3) s = {n.scale[0], n.scale[1], n.scale[2]};
      if (n.rotation.size() == 4)  // glTF: x, y, z, w
        r = glm::quat(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                      static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
      m = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    }
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(m)[i])) fail(path_, place, "non-finite transform");
    return m;
  }

  // Walks the tree under `root` depth first, parents before children, with a stack of its own:
  // a recursion as deep as the file's hierarchy could exhaust the thread's stack.
  void visit(int root) {
    struct Level {
      int node;
      glm::mat4 world;
      size_t next_child;
    };
    std::vector<Level> path;
    if (on_path_.empty()) {
      on_path_.resize(model_.nodes.size(), false);
      visited_.resize(model_.nodes.size(), false);
    }
    auto enter = [&](int index, const glm::mat4& parent, const std::string& from) {
      if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
        fail(path_, from, fmt::format("node {} does not exist", index));
      const std::string place = fmt::format("nodes[{}]", index);
      if (on_path_[index]) fail(path_, place, "cycle in the node hierarchy");
      // Nodes form trees (glTF 2.0, 3.5.3): a node met twice would be drawn twice, and shared
      // children would multiply the work exponentially.
      if (visited_[index]) fail(path_, place, "node reached twice (a node has at most one parent and is no root besides)");
      visited_[index] = on_path_[index] = true;
      const tinygltf::Node& n = model_.nodes[index];
      const glm::mat4 world = parent * local_matrix(n, place);
      if (n.mesh >= 0) {
        if (static_cast<size_t>(n.mesh) >= model_.meshes.size())
          fail(path_, place, fmt::format("mesh {} does not exist", n.mesh));
        const tinygltf::Mesh& mesh = model_.meshes[n.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); ++p)
          add_primitive(mesh, mesh.primitives[p], fmt::format("meshes[{}].primitives[{}]", n.mesh, p),
                        world, n.name.empty() ? place : n.name);
      }
      path.push_back(Level{index, world, 0});
    };
    enter(root, glm::mat4(1.0f), "scene");
    while (!path.empty()) {
      Level& top = path.back();
      const std::vector<int>& children = model_.nodes[top.node].children;
      if (top.next_child < children.size()) {
        const int child = children[top.next_child++];
        const glm::mat4 world = top.world;  // `top` moves when enter() grows `path`
        enter(child, world, fmt::format("nodes[{}]", top.node));
      } else {
        on_path_[top.node] = false;
        path.pop_back();
      }
    }
  }

  AccessorView view(int index, const std::string& from) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
      fail(path_, from, fmt::format("accessor {} does not exist", index));
    const tinygltf::Accessor& a = model_.accessors[index];
    const std::string place = fmt::format("accessors[{}]", index);
    if (a.sparse.isSparse) fail(path_, place, "sparse accessors are not supported");
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
      fail(path_, place, fmt::format("bufferView {} does not exist", a.bufferView));
    const tinygltf::BufferView& bv = model_.bufferViews[a.bufferView];
    const std::string bv_place = fmt::format("bufferViews[{}]", a.bufferView);
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
      fail(path_, bv_place, fmt::format("buffer {} does not exist", bv.buffer));
    const std::vector<unsigned char>& buf = model_.buffers[bv.buffer].data;
    if (bv.byteOffset > buf.size() || bv.byteLength > buf.size() - bv.byteOffset)
      fail(path_, bv_place, fmt::format("bytes {} to {} lie outside buffer {} ({} bytes)", bv.byteOffset,
                                        bv.byteOffset + bv.byteLength, bv.buffer, buf.size()));
    const int cs = component_size(a.componentType), cc = component_count(a.type);
    if (cs == 0 || cc == 0) fail(path_, place, "unsupported componentType or type");
    const size_t elem = static_cast<size_t>(cs) * cc;
    const size_t stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem) fail(path_, bv_place, fmt::format("byteStride {} is less than the element size {}", stride, elem));
    AccessorView v;
    v.count = a.count;
    v.stride = stride;
    v.component = a.componentType;
    if (a.count > 0) {
      if (a.byteOffset > bv.byteLength || bv.byteLength - a.byteOffset < elem ||
          (a.count - 1) > (bv.byteLength - a.byteOffset - elem) / stride)
        fail(path_, place, fmt::format("{} elements run past the end of bufferView {}", a.count, a.bufferView));
      v.data = buf.data() + bv.byteOffset + a.byteOffset;
    }
    return v;
  }

  std::vector<glm::vec3> read_vec3(int index, const std::string& from) const {
    const AccessorView v = view(index, from);
    const tinygltf::Accessor& a = model_.accessors[index];
    const std::string place = fmt::format("accessors[{}]", index);
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(path_, place, "expected VEC3 of FLOAT");
    std::vector<glm::vec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      std::memcpy(&out[i], v.data + i * v.stride, 12);
      if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
        fail(path_, place, fmt::format("element {} is not finite", i));
    }
    return out;
  }

  std::vector<uint32_t> read_indices(int index, size_t vertex_count, const std::string& from) const {
    const AccessorView v = view(index, from);
    const std::string place = fmt::format("accessors[{}]", index);
    if (model_.accessors[index].type != TINYGLTF_TYPE_SCALAR ||
        (v.component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         v.component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         v.component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail(path_, place, "indices must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      uint32_t x = 0;
      if (v.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        x = *p;
      } else if (v.component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t s = 0;
        std::memcpy(&s, p, 2);
        x = s;
      } else {
        std::memcpy(&x, p, 4);
      }
      if (x >= vertex_count)
        fail(path_, place, fmt::format("element {}: index {} out of range ({} vertices)", i, x, vertex_count));
      out[i] = x;
    }
    return out;
  }

  void add_primitive(const tinygltf::Mesh& mesh, const tinygltf::Primitive& prim, const std::string& place,
                     const glm::mat4& world, const std::string& node_name) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode <= TINYGLTF_MODE_LINE_STRIP) {
      ++ignored_;  // points and lines: no triangles to draw
      return;
    }
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN) fail(path_, place, fmt::format("unknown mode {}", mode));
    uint32_t material;
    if (prim.material < 0) {
      material = static_cast<uint32_t>(model_.materials.size());
      default_used_ = true;
    } else if (static_cast<size_t>(prim.material) >= model_.materials.size()) {
      fail(path_, place, fmt::format("material {} does not exist", prim.material));
    } else {
      material = static_cast<uint32_t>(prim.material);
      if (dropped_[material]) {
        ++masked_;
        return;
      }
    }
    const auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) fail(path_, place, "no POSITION attribute");
    const std::vector<glm::vec3> positions = read_vec3(pos_it->second, place);
    std::vector<glm::vec3> normals;
    if (const auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end()) {
      normals = read_vec3(n->second, place);
      if (normals.size() != positions.size())
        fail(path_, fmt::format("accessors[{}]", n->second),
             fmt::format("NORMAL has {} elements, POSITION {}", normals.size(), positions.size()));
    }
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
      idx = read_indices(prim.indices, positions.size(), place);
    } else {
      idx.resize(positions.size());
      for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<uint32_t>(i);
    }
    MeshBuilder b{positions, normals, {}, {}};
    const bool have_n = !normals.empty();
    auto emit = [&](uint32_t i0, uint32_t i1, uint32_t i2) {
      const uint32_t p[3] = {i0, i1, i2};
      const int64_t n[3] = {have_n ? i0 : -1, have_n ? i1 : -1, have_n ? i2 : -1};
      b.add(p, n);
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (idx.size() % 3 != 0)
        fail(path_, place, fmt::format("{} indices is not a multiple of 3", idx.size()));
      for (size_t i = 0; i + 2 < idx.size(); i += 3) emit(idx[i], idx[i + 1], idx[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < idx.size(); ++i)
        emit(idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]);
    } else {
      for (size_t i = 1; i + 1 < idx.size(); ++i) emit(idx[i], idx[i + 1], idx[0]);
    }
    if (b.mesh.triangles.empty()) return;
    for (const glm::vec3& p : b.mesh.positions) {
      const glm::vec4 w = world * glm::vec4(p, 1.0f);
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
        fail(path_, place, "the node transform gives non-finite coordinates");
    }
    Object obj;
    obj.name = mesh.name.empty() ? node_name : node_name + "/" + mesh.name;
    obj.mesh = std::move(b.mesh);
    obj.material = material;
    obj.transform = world;
    scene_.objects.push_back(std::move(obj));
  }

  const std::string& path_;
  const tinygltf::Model& model_;
  Scene scene_;
  std::vector<bool> dropped_;
  std::vector<bool> on_path_;
  std::vector<bool> visited_;
  bool default_used_ = false;
  size_t ignored_ = 0;
  size_t masked_ = 0;
};

// Syntax and nesting depth of JSON text, without building it. tinygltf turns `extras` into
// values recursively: deep nesting would exhaust the stack there.
class JsonCheck : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string error;  // the parser's message when malformed
  bool too_deep = false;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return enter(); }
  bool key(string_t&) override { return true; }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t) override { return enter(); }
  bool end_array() override { return leave(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    return false;
  }

 private:
  bool enter() {
    too_deep = ++depth_ > kMaxJsonDepth;
    return !too_deep;
  }
  bool leave() {
    --depth_;
    return true;
  }
  size_t depth_ = 0;
};

// "%20" and the like, as tinygltf decodes a buffer's uri.
std::string percent_decode(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// ---- glTF property types: tinygltf silently skips a property of the wrong type ----

enum class JsonKind { kIndex, kSize, kLength, kNumber, kString, kBool, kObject };

// One property: `array` -1 for a single value, 0 for an array of any length, n for exactly n.
struct JsonField {
  const char* name;
  JsonKind kind;
  int array = -1;
};

bool json_is(const nlohmann::json& v, JsonKind k) {
  switch (k) {
    case JsonKind::kIndex: return v.is_number_unsigned() && v.get<uint64_t>() <= uint64_t{INT32_MAX};
    case JsonKind::kSize: return v.is_number_unsigned();
    case JsonKind::kLength: return v.is_number_unsigned() && v.get<uint64_t>() > 0;
    case JsonKind::kNumber: return v.is_number();
    case JsonKind::kString: return v.is_string();
    case JsonKind::kBool: return v.is_boolean();
    case JsonKind::kObject: return v.is_object();
  }
  return false;
}

const char* json_kind_name(JsonKind k) {
  switch (k) {
    case JsonKind::kIndex: return "an index (an integer from 0 to 2^31 - 1)";
    case JsonKind::kSize: return "a non-negative integer";
    case JsonKind::kLength: return "a positive integer";
    case JsonKind::kNumber: return "a number";
    case JsonKind::kString: return "a string";
    case JsonKind::kBool: return "true or false";
    case JsonKind::kObject: return "an object";
  }
  return "?";
}

// "string \"abc\"", "number -1", "array": what was found instead.
std::string json_found(const nlohmann::json& v) {
  if (v.is_array() || v.is_object()) return v.type_name();
  std::string text = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > 24) text = text.substr(0, 21) + "...";
  return fmt::format("{} {}", v.type_name(), text);
}

void check_fields(const std::string& path, const nlohmann::json& obj, const std::string& place,
                  std::initializer_list<JsonField> fields) {
  for (const JsonField& f : fields) {
    const auto it = obj.find(f.name);
    if (it == obj.end()) continue;
    const std::string at = place.empty() ? f.name : place + "." + f.name;
    auto expect = [&](const nlohmann::json& v, const std::string& where) {
      if (!json_is(v, f.kind))
        fail(path, where, fmt::format("expected {}, not {}", json_kind_name(f.kind), json_found(v)));
    };
    if (f.array < 0) {
      expect(*it, at);
      continue;
    }
    if (!it->is_array()) fail(path, at, fmt::format("expected an array, not {}", json_found(*it)));
    if (f.array > 0 && it->size() != size_t(f.array))
      fail(path, at, fmt::format("expected {} numbers, has {}", f.array, it->size()));
    for (size_t i = 0; i < it->size(); ++i) expect((*it)[i], fmt::format("{}[{}]", at, i));
  }
}

// Calls f(element, place) for each element of the array property `name`, each an object.
template <typename F>
void for_each_object(const std::string& path, const nlohmann::json& parent, const std::string& place,
                     const char* name, F&& f) {
  const auto it = parent.find(name);
  if (it == parent.end()) return;
  const std::string at = place.empty() ? name : place + "." + name;
  if (!it->is_array()) fail(path, at, fmt::format("expected an array, not {}", json_found(*it)));
  for (size_t i = 0; i < it->size(); ++i) {
    const std::string item = fmt::format("{}[{}]", at, i);
    if (!(*it)[i].is_object()) fail(path, item, fmt::format("expected an object, not {}", json_found((*it)[i])));
    f((*it)[i], item);
  }
}

// The types of every property zblend reads (glTF 2.0 schema).
void check_gltf_types(const std::string& path, const char* json_place, const nlohmann::json& doc) {
  using K = JsonKind;
  if (!doc.is_object()) fail(path, json_place, fmt::format("expected an object, not {}", json_found(doc)));
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) fail(path, "asset", "missing (glTF 2.0 needs \"asset\": {\"version\": \"2.0\"})");
  const auto version = asset->find("version");
  if (version == asset->end() || !version->is_string() || version->get_ref<const std::string&>().rfind("2.", 0) != 0)
    fail(path, "asset.version", fmt::format("{} is not supported (expected \"2.0\")",
                                            version == asset->end() ? "no version" : json_found(*version)));
  check_fields(path, doc, "", {{"scene", K::kIndex}});
  for_each_object(path, doc, "", "scenes", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at, {{"nodes", K::kIndex, 0}});
  });
  for_each_object(path, doc, "", "nodes", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at,
                 {{"children", K::kIndex, 0}, {"mesh", K::kIndex}, {"matrix", K::kNumber, 16},
                  {"translation", K::kNumber, 3}, {"rotation", K::kNumber, 4}, {"scale", K::kNumber, 3},
                  {"name", K::kString}});
  });
  for_each_object(path, doc, "", "meshes", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at, {{"name", K::kString}});
    for_each_object(path, o, at, "primitives", [&](const nlohmann::json& p, const std::string& pat) {
      check_fields(path, p, pat, {{"attributes", K::kObject}, {"indices", K::kIndex}, {"material", K::kIndex},
                                  {"mode", K::kIndex}});
      if (const auto a = p.find("attributes"); a != p.end())
        for (const auto& [key, value] : a->items())
          if (!json_is(value, K::kIndex))
            fail(path, pat + ".attributes." + key,
                 fmt::format("expected {}, not {}", json_kind_name(K::kIndex), json_found(value)));
    });
  });
  for_each_object(path, doc, "", "accessors", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at,
                 {{"bufferView", K::kIndex}, {"byteOffset", K::kSize}, {"componentType", K::kIndex},
                  {"count", K::kSize}, {"type", K::kString}, {"normalized", K::kBool}, {"sparse", K::kObject}});
  });
  for_each_object(path, doc, "", "bufferViews", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at,
                 {{"buffer", K::kIndex}, {"byteOffset", K::kSize}, {"byteLength", K::kLength}, {"byteStride", K::kSize}});
  });
  for_each_object(path, doc, "", "buffers", [&](const nlohmann::json& o, const std::string& at) {
    // An empty GLB buffer makes tinygltf throw (found by fuzz_gltf); the schema forbids it.
    check_fields(path, o, at, {{"uri", K::kString}, {"byteLength", K::kLength}});
  });
  for_each_object(path, doc, "", "materials", [&](const nlohmann::json& o, const std::string& at) {
    check_fields(path, o, at,
                 {{"name", K::kString}, {"alphaMode", K::kString}, {"alphaCutoff", K::kNumber},
                  {"doubleSided", K::kBool}, {"pbrMetallicRoughness", K::kObject}});
    if (const auto pbr = o.find("pbrMetallicRoughness"); pbr != o.end())
      check_fields(path, *pbr, at + ".pbrMetallicRoughness", {{"baseColorFactor", K::kNumber, 4}});
  });
}

// tinygltf's file access goes through the SceneFileReader, each file read once. Names are not
// expanded: tinygltf's own expansion runs wordexp on text from the file.
struct GltfFiles {
  const SceneFileReader& read;
  std::map<std::string, std::string> found;

  FileRead get(const std::string& path, const std::string** bytes) {
    auto it = found.find(path);
    if (it == found.end()) {
      std::string b;
      const FileRead r = read(path, b);
      if (r != FileRead::kOk) return r;
      it = found.emplace(path, std::move(b)).first;
    }
    if (bytes) *bytes = &it->second;
    return FileRead::kOk;
  }

  static bool exists(const std::string& path, void* self) {
    return static_cast<GltfFiles*>(self)->get(path, nullptr) == FileRead::kOk;
  }
  static std::string expand(const std::string& path, void*) { return path; }
  static bool read_whole(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
    const std::string* bytes = nullptr;
    if (static_cast<GltfFiles*>(self)->get(path, &bytes) != FileRead::kOk) {
      if (err) *err = "cannot read the file";
      return false;
    }
    out->assign(bytes->begin(), bytes->end());
    return true;
  }
  static bool write_whole(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "zblend writes no glTF files";
    return false;
  }
};

// Each buffer in a file of its own must exist and hold byteLength bytes; tinygltf's messages
// for these lack the buffer's index.
void check_buffer_files(const std::string& path, const nlohmann::json& doc, GltfFiles& files) {
  const auto buffers = doc.is_object() ? doc.find("buffers") : doc.end();
  if (buffers == doc.end() || !buffers->is_array()) return;  // tinygltf reports the rest
  for (size_t i = 0; i < buffers->size(); ++i) {
    const nlohmann::json& b = (*buffers)[i];
    const auto uri = b.is_object() ? b.find("uri") : b.end();
    if (uri == b.end() || !uri->is_string()) continue;
    const std::string& text = uri->get_ref<const std::string&>();
    if (text.empty() || text.rfind("data:", 0) == 0) continue;
    const std::string file = beside(path, percent_decode(text));
    const std::string place = fmt::format("buffers[{}]", i);
    const std::string* bytes = nullptr;
    const FileRead r = files.get(file, &bytes);
    if (r == FileRead::kMissing) fail(path, place, fmt::format("file '{}' not found", file));
    if (r != FileRead::kOk) fail(path, place, fmt::format("cannot read file '{}'", file));
    const auto length = b.find("byteLength");
    if (length != b.end() && length->is_number_unsigned() && length->get<uint64_t>() != bytes->size())
      fail(path, place, fmt::format("file '{}' has {} bytes, byteLength says {}", file, bytes->size(),
                                    length->get<uint64_t>()));
  }
}

}  // namespace

Scene load_gltf(const std::string& path, const std::string& data, bool binary, const SceneFileReader& read) {
  const std::string json = binary ? glb_json_chunk(path, data) : data;
  const char* json_place = binary ? "JSON chunk" : "JSON";
  JsonCheck check;
  if (!nlohmann::json::sax_parse(json, &check)) {
    if (check.too_deep) fail(path, json_place, fmt::format("nested deeper than {} levels", kMaxJsonDepth));
    std::string what = check.error;
    if (const size_t b = what.find("] "); b != std::string::npos) what.erase(0, b + 2);
    fail(path, json_place, "malformed: " + one_line(what));
  }
  const nlohmann::json doc = nlohmann::json::parse(json);
  check_gltf_types(path, json_place, doc);
  GltfFiles files{read, {}};
  check_buffer_files(path, doc, files);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&GltfFiles::exists, &GltfFiles::expand, &GltfFiles::read_whole,
                                              &GltfFiles::write_whole, &files});
  tinygltf::Model model;
  std::string err, warn;
  const std::string base = fs::path(path).parent_path().string();
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(data.data()),
                                           static_cast<unsigned int>(data.size()), base)
             : loader.LoadASCIIFromString(&model, &err, &warn, data.c_str(),
                                          static_cast<unsigned int>(data.size()), base);
  if (!ok) fail(path, "tinygltf", one_line(err));
  return GltfReader(path, model).read();
}

}  // namespace zb
