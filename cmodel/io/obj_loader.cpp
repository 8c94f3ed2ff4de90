// Wavefront OBJ and MTL (docs/scenes.md). tinyobjloader is lenient ("v abc" reads as 0, a short
// face is dropped), so each file is first checked here line by line, and every problem is
// reported with its line. Debian's shared library holds the loader's implementation.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <fmt/core.h>
#include <tiny_obj_loader.h>

#include "io/internal/loaders.h"
#include "io/internal/mesh_builder.h"
#include "io/internal/text.h"

namespace zb {

using namespace text;

namespace {

// ---- OBJ and MTL -----------------------------------------------------------------------------

// What tinyobjloader is given: only the statements zblend reads, each line as the checks split
// it (blank lines keep the numbering), so that its own parser meets nothing the checks have not
// seen. Found by fuzzing: it converts a `vw` joint id to int unchecked (undefined when huge),
// and it ends a line at a lone '\r', where the checks do not.
struct CheckedText {
  std::string text;
  int lines = 0;

  void add(int line, const std::vector<std::string>& tok) {
    for (; lines < line - 1; ++lines) text += '\n';
    for (size_t i = 0; i < tok.size(); ++i) text += (i ? " " : "") + tok[i];
    text += '\n';
    ++lines;
  }
};

// The statements zblend reads (newmtl, Kd, d, Tr); returns them alone. The materials with a
// diffuse texture (map_Kd, not read) go to `textured`, named as tinyobjloader names them.
std::string check_mtl(const std::string& path, const std::string& text,
                      std::set<std::string>& textured) {
  bool have_material = false;
  std::string material;
  CheckedText kept;
  for_each_line(text, [&](int line, const std::vector<std::string>& tok) {
    const std::string& key = tok[0];
    if (key == "newmtl") {
      if (tok.size() < 2) fail(path, fmt::format("line {}", line), "'newmtl' without a name");
      have_material = true;
      material = tok[1];
      for (size_t i = 2; i < tok.size(); ++i) material += " " + tok[i];
    } else if (key == "map_Kd") {
      if (have_material) textured.insert(material);
      return;
    } else if (key == "Kd" || key == "d" || key == "Tr") {
      if (!have_material) fail(path, fmt::format("line {}", line), fmt::format("'{}' before any 'newmtl'", key));
      expect_numbers(path, line, tok, 1, key == "Kd" ? 3 : 1, true);
    } else {
      return;
    }
    kept.add(line, tok);
  });
  return kept.text;
}

// What check_obj learnt: the statements for tinyobjloader, each material library's (checked
// statements) by its name in the OBJ, and the line of each vertex.
struct ObjCheck {
  std::string text;
  std::map<std::string, std::string> mtl_texts;
  std::set<std::string> textured;  // materials with a texture
  std::vector<int> vertex_lines;
};

// Vertices, normals and faces with their indices, and the material libraries, line by line.
ObjCheck check_obj(const std::string& path, const std::string& text, const SceneFileReader& read) {
  ObjCheck out;
  CheckedText kept;
  size_t nv = 0, nvt = 0, nvn = 0;
  for_each_line(text, [&](int line, const std::vector<std::string>& tok) {
    const std::string place = fmt::format("line {}", line);
    const std::string& key = tok[0];
    if (key == "v") {
      expect_numbers(path, line, tok, 1, 3, false);
      out.vertex_lines.push_back(line);
      ++nv;
    } else if (key == "vn") {
      expect_numbers(path, line, tok, 1, 3, false);
      ++nvn;
    } else if (key == "vt") {
      expect_numbers(path, line, tok, 1, 1, false);
      ++nvt;
    } else if (key == "f") {
      if (tok.size() < 4) fail(path, place, fmt::format("a face needs 3 vertices, has {}", tok.size() - 1));
      for (size_t i = 1; i < tok.size(); ++i) {
        const std::vector<std::string> parts = split(tok[i], '/');
        const size_t counts[3] = {nv, nvt, nvn};
        const char* names[3] = {"vertex", "texture coordinate", "normal"};
        if (parts.size() > 3) fail(path, place, fmt::format("bad face vertex '{}'", tok[i]));
        for (size_t k = 0; k < parts.size(); ++k) {
          if (k > 0 && parts[k].empty()) continue;  // v//vn
          long idx = 0;
          if (!parse_int(parts[k], idx) || idx == 0)
            fail(path, place, fmt::format("bad face vertex '{}'", tok[i]));
          const long n = static_cast<long>(counts[k]);
          if ((idx > 0 && idx > n) || (idx < 0 && -idx > n))
            fail(path, place, fmt::format("{} index {} out of range (1 to {})", names[k], idx, n));
        }
      }
    } else if (key == "mtllib") {
      if (tok.size() < 2) fail(path, place, "'mtllib' without a file name");
      for (size_t i = 1; i < tok.size(); ++i) {
        if (out.mtl_texts.count(tok[i])) continue;
        const std::string mtl = beside(path, tok[i]);
        std::string mtl_text;
        const FileRead r = read(mtl, mtl_text);
        if (r == FileRead::kMissing) fail(path, place, fmt::format("material library '{}' not found", mtl));
        if (r != FileRead::kOk) fail(mtl, "mtllib", "cannot read the file");
        out.mtl_texts.emplace(tok[i], check_mtl(mtl, mtl_text, out.textured));
      }
    } else if (key == "usemtl") {
      if (tok.size() < 2) fail(path, place, "'usemtl' without a name");
    } else if (key != "o" && key != "g") {
      return;  // not read: smoothing groups, lines, points, free-form geometry, skin weights
    }
    kept.add(line, tok);
  });
  out.text = std::move(kept.text);
  return out;
}

// Gives tinyobjloader the material libraries check_obj has read and checked, nothing else.
class CheckedMtlReader : public tinyobj::MaterialReader {
 public:
  explicit CheckedMtlReader(const std::map<std::string, std::string>& texts) : texts_(texts) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) override {
    const auto it = texts_.find(name);
    if (it == texts_.end()) return false;  // a name tinyobjloader splits otherwise (escaped blanks)
    std::istringstream in(it->second);
    tinyobj::LoadMtl(by_name, materials, &in, warn, err);
    return true;
  }

 private:
  const std::map<std::string, std::string>& texts_;
};

}  // namespace

Scene load_obj(const std::string& path, const std::string& text, const SceneFileReader& read) {
  const ObjCheck checked = check_obj(path, text, read);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> mats;
  std::string warn, err;
  {
    // A stream over the checked text itself: an istringstream would hold a third copy of the
    // file at the loader's peak.
    struct TextBuf : std::streambuf {
      explicit TextBuf(const std::string& t) {
        char* p = const_cast<char*>(t.data());  // read only: the get area is never written
        setg(p, p, p + t.size());
      }
    } buf(checked.text);
    std::istream in(&buf);
    CheckedMtlReader mtl_reader(checked.mtl_texts);
    if (!tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, &mtl_reader, true))
      fail(path, "tinyobjloader", one_line(err));
  }

  Scene scene;
  scene.name = path;
  // tinyobjloader: `d` is the dissolve; `Tr` alone sets dissolve = 1 - Tr.
  for (const tinyobj::material_t& m : mats) {
    Material mat;
    mat.name = m.name;
    mat.color = {to_unorm8(m.diffuse[0]), to_unorm8(m.diffuse[1]), to_unorm8(m.diffuse[2]),
                 to_unorm8(m.dissolve)};
    scene.materials.push_back(mat);
  }
  const auto default_material = static_cast<uint32_t>(scene.materials.size());
  bool used_default = false;

  std::vector<glm::vec3> positions(attrib.vertices.size() / 3), normals(attrib.normals.size() / 3);
  for (size_t i = 0; i < positions.size(); ++i) {
    positions[i] = {attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
    // tinyobjloader has its own number parser: what it reads is checked again.
    if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
      fail(path, i < checked.vertex_lines.size() ? fmt::format("line {}", checked.vertex_lines[i]) : "tinyobjloader",
           "vertex coordinate is not finite");
  }
  for (size_t i = 0; i < normals.size(); ++i) {
    normals[i] = {attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]};
    if (!std::isfinite(normals[i].x) || !std::isfinite(normals[i].y) || !std::isfinite(normals[i].z))
      normals[i] = glm::vec3(0.0f);  // unusable: the flat face normal is used instead
  }

  for (size_t s = 0; s < shapes.size(); ++s) {
    const tinyobj::mesh_t& m = shapes[s].mesh;
    // One object per shape, split further by material (Object has one material).
    std::vector<int> order;
    std::map<int, MeshBuilder> builders;
    // Triangles per material, so each mesh is allocated once (growth by doubling would hold
    // old and new arrays at the loader's peak): at most three vertices per triangle.
    std::map<int, size_t> tri_count;
    for (size_t f = 0; f < m.num_face_vertices.size(); ++f) {
      if (m.num_face_vertices[f] != 3) continue;
      const int mat = f < m.material_ids.size() ? m.material_ids[f] : -1;
      ++tri_count[(mat < 0 || static_cast<size_t>(mat) >= mats.size()) ? -1 : mat];
    }
    size_t offset = 0;
    for (size_t f = 0; f < m.num_face_vertices.size(); ++f) {
      const size_t nfv = m.num_face_vertices[f];
      if (nfv > m.indices.size() - offset)
        fail(path, fmt::format("shape '{}'", shapes[s].name), "face indices out of range");
      if (nfv == 3) {
        int mat = f < m.material_ids.size() ? m.material_ids[f] : -1;
        if (mat < 0 || static_cast<size_t>(mat) >= mats.size()) mat = -1;
        auto it = builders.find(mat);
        if (it == builders.end()) {
          it = builders.emplace(mat, MeshBuilder{positions, normals, {}, {}}).first;
          const size_t tris = tri_count[mat];
          it->second.mesh.triangles.reserve(tris);
          it->second.mesh.positions.reserve(3 * tris);
          it->second.mesh.normals.reserve(3 * tris);
          order.push_back(mat);
        }
        uint32_t p[3];
        int64_t n[3];
        for (int k = 0; k < 3; ++k) {
          const tinyobj::index_t& ix = m.indices[offset + k];
          if (ix.vertex_index < 0 || static_cast<size_t>(ix.vertex_index) >= positions.size())
            fail(path, fmt::format("shape '{}'", shapes[s].name), "vertex index out of range");
          p[k] = static_cast<uint32_t>(ix.vertex_index);
          n[k] = ix.normal_index;
        }
        it->second.add(p, n);
      }
      offset += nfv;
    }
    for (int mat : order) {
      Object obj;
      obj.name = shapes[s].name.empty() ? fmt::format("shape {}", s) : shapes[s].name;
      if (order.size() > 1) obj.name += "/" + (mat < 0 ? std::string("default") : mats[mat].name);
      obj.mesh = std::move(builders.at(mat).mesh);
      obj.mesh.positions.shrink_to_fit();  // shared corners: fewer than reserved
      obj.mesh.normals.shrink_to_fit();
      obj.material = mat < 0 ? default_material : static_cast<uint32_t>(mat);
      used_default = used_default || mat < 0;
      scene.objects.push_back(std::move(obj));
    }
  }
  if (used_default) scene.materials.push_back(Material{"default", {255, 255, 255, 255}});
  warn_ignored_textures(scene, [&](uint32_t m) {
    return m < mats.size() && checked.textured.count(mats[m].name) > 0;
  });
  scene.description = fmt::format("OBJ file, {} shapes, {} materials", shapes.size(), mats.size());
  return scene;
}

}  // namespace zb
