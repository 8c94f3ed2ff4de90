// Scene file tests: small OBJ, MTL, glTF and GLB files written here with hand-derived
// expectations, every malformed case, the camera, and real files from Debian packages
// (assimp-testmodels, glmark2-data; scripts/setup.sh installs them).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "io/scene_file.h"
#include "scene/camera.h"

namespace zb {
namespace {

namespace fs = std::filesystem;

class SceneFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "zb-scene-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // The SceneFileError message of loading `path`; empty (and a failure) if it loads.
  static std::string error_of(const std::string& path) {
    try {
      load_scene_file(path);
    } catch (const SceneFileError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return e.what();
    }
    ADD_FAILURE() << path << " loaded";
    return "";
  }

  fs::path dir_;
};

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

// ---- OBJ and MTL -----------------------------------------------------------------------------

const char* kMtl =
    "# two materials\n"
    "newmtl red\nKd 1 0 0\nd 0.5\n"
    "newmtl blue\nKd 0 0 1\nTr 0.25\n";

const char* kObj =
    "mtllib t.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
    "o tri\nusemtl red\nf 1 2 3\n"
    "o quad\nusemtl blue\nf 1 2 4 3\n";

TEST_F(SceneFileTest, ObjPositionsColoursAlphas) {
  write("t.mtl", kMtl);
  const Scene s = load_scene_file(write("t.obj", kObj));
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].name, "tri");
  EXPECT_EQ(s.objects[1].name, "quad");
  EXPECT_EQ(s.triangle_count(), 3u);  // the quad triangulated into 2
  const Material& red = s.materials.at(s.objects[0].material);
  const Material& blue = s.materials.at(s.objects[1].material);
  // Kd 1 0 0, d 0.5 -> alpha round(127.5) = 128; Tr 0.25 -> d 0.75 -> round(191.25) = 191.
  EXPECT_EQ(red.color, (Rgba8{255, 0, 0, 128}));
  EXPECT_EQ(blue.color, (Rgba8{0, 0, 255, 191}));
  // No normals in the file: flat, each triangle its own vertices, normal +z (CCW in z = 0).
  const Mesh& tri = s.objects[0].mesh;
  ASSERT_EQ(tri.positions.size(), 3u);
  EXPECT_EQ(tri.positions[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(tri.positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(tri.positions[2], glm::vec3(0, 1, 0));
  for (const glm::vec3& n : tri.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  EXPECT_EQ(s.background, (Rgba8{255, 255, 255, 255}));
}

TEST_F(SceneFileTest, ObjNormalsFromTheFileAreShared) {
  const Scene s = load_scene_file(write("n.obj",
      "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nvn 0 0 3\nf 1//1 2//1 4//1\nf 1//1 4//1 3//1\n"));
  ASSERT_EQ(s.objects.size(), 1u);
  const Mesh& m = s.objects[0].mesh;
  EXPECT_EQ(m.positions.size(), 4u);  // shared (position, normal) pairs
  EXPECT_EQ(m.triangles.size(), 2u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));  // normalized
  // No mtllib: the default white opaque material.
  EXPECT_EQ(s.materials.at(s.objects[0].material).color, (Rgba8{255, 255, 255, 255}));
}

TEST_F(SceneFileTest, FittedCameraFramesTheBounds) {
  // A 2 x 2 quad in z = 0 around (3, 4, 0): sphere centre (3, 4, 0), radius sqrt(2).
  const Scene s = load_scene_file(write("q.obj", "v 2 3 0\nv 4 3 0\nv 4 5 0\nv 2 5 0\nf 1 2 3 4\n"));
  const float r = std::sqrt(2.0f);
  const float d = r / std::sin(glm::radians(22.5f));
  EXPECT_EQ(s.camera.at, glm::vec3(3, 4, 0));
  EXPECT_NEAR(s.camera.eye.x, 3.0f, 1e-6f);
  EXPECT_NEAR(s.camera.eye.y, 4.0f, 1e-6f);
  EXPECT_NEAR(s.camera.eye.z, d, 1e-5f);
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, 45.0f);
  EXPECT_NEAR(s.camera.near, d - 1.01f * r, 1e-5f);
  EXPECT_NEAR(s.camera.far, d + 1.01f * r, 1e-5f);
  // Every corner inside the view volume at aspect 1; the sphere touches the top and bottom.
  const glm::mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  for (const glm::vec3& p : s.objects[0].mesh.positions) {
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::fabs(c[k] / c.w), 1.0f) << k;
  }
}

TEST_F(SceneFileTest, ObjErrorsNameFileLineAndProblem) {
  const std::string missing = (dir_ / "nope.obj").string();
  EXPECT_EQ(error_of(missing), missing + ": open: no such file");
  std::string p = write("a.obj", "v 0 0 0\nv 1 2\n");  // truncated
  EXPECT_EQ(error_of(p), p + ": line 2: 'v' needs 3 numbers, has 2");
  p = write("b.obj", "v nan 0 0\n");
  EXPECT_EQ(error_of(p), p + ": line 1: 'v': nan is not finite");
  p = write("c.obj", "v 0 0 0\nv 1e39 0 0\n");
  EXPECT_EQ(error_of(p), p + ": line 2: 'v': 1e39 is not finite");
  p = write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  EXPECT_EQ(error_of(p), p + ": line 4: vertex index 9 out of range (1 to 3)");
  p = write("e.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  EXPECT_EQ(error_of(p), p + ": line 4: a face needs 3 vertices, has 2");
  p = write("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 x 3\n");
  EXPECT_EQ(error_of(p), p + ": line 4: bad face vertex 'x'");
  p = write("g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(error_of(p), "scene '" + p + "': no triangles");
  p = write("h.obj", "v 0 0 0\nvn 0 inf 0\n");
  EXPECT_EQ(error_of(p), p + ": line 2: 'vn': inf is not finite");
}

TEST_F(SceneFileTest, MtlErrorsNameTheMaterialFile) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string p = write("m.obj", obj);
  EXPECT_EQ(error_of(p), p + ": line 1: material library '" + (dir_ / "m.mtl").string() + "' not found");
  const std::string mtl = write("m.mtl", "newmtl a\nKd 1 x 0\n");
  EXPECT_EQ(error_of(p), mtl + ": line 2: 'Kd': 'x' is not a number");
  write("m.mtl", "newmtl a\nKd 1 1\n");  // truncated
  EXPECT_EQ(error_of(p), mtl + ": line 2: 'Kd' needs 3 numbers, has 2");
  write("m.mtl", "newmtl a\nd 1.5\n");
  EXPECT_EQ(error_of(p), mtl + ": line 2: 'd': 1.5 is outside 0 to 1");
  write("m.mtl", "Kd 1 1 1\n");
  EXPECT_EQ(error_of(p), mtl + ": line 1: 'Kd' before any 'newmtl'");
}

TEST_F(SceneFileTest, UnsupportedExtension) {
  const std::string p = write("x.ply", "ply\n");
  EXPECT_EQ(error_of(p), p + ": name: unsupported file type '.ply' (expected .obj, .gltf or .glb)");
  EXPECT_TRUE(is_scene_path("a/b"));
  EXPECT_TRUE(is_scene_path("X.GLB"));
  EXPECT_FALSE(is_scene_path("cad"));
}

// ---- glTF and GLB ----------------------------------------------------------------------------

// The binary buffer: 4 positions (48 bytes) then 6 unsigned short indices (12 bytes).
std::string test_buffer(float x1 = 1.0f, uint16_t last_index = 3) {
  const float pos[12] = {0, 0, 0, x1, 0, 0, 0, 1, 0, 1, 1, 0};
  const uint16_t idx[6] = {0, 1, 2, 1, 3, last_index};
  std::string b(60, '\0');
  std::memcpy(b.data(), pos, 48);
  std::memcpy(b.data() + 48, idx, 12);
  return b;
}

// Node 0 (translation 1,2,3) has child node 1 (scale 2) with mesh 0; node 2 (a matrix that
// translates by 10 in x) has mesh 1. Mesh 0: an indexed BLEND primitive, a non-indexed OPAQUE
// one, a MASK one kept and a MASK one dropped, and a line primitive (ignored).
std::string test_gltf(const std::string& buffer_json, int idx_count = 6, const std::string& extra = "") {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 2]}],
  "nodes": [{"translation": [1, 2, 3], "children": [1]}, {"scale": [2, 2, 2], "mesh": 0},
            {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 10,0,0,1], "mesh": 1}],
  "meshes": [{"primitives": [
      {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
      {"attributes": {"POSITION": 2}, "material": 1},
      {"attributes": {"POSITION": 2}, "material": 2},
      {"attributes": {"POSITION": 2}, "material": 3},
      {"attributes": {"POSITION": 0}, "mode": 1}]},
    {"primitives": [{"attributes": {"POSITION": 2}}]}],
  "materials": [
    {"name": "glass", "alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 0.5]}},
    {"name": "solid", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 0.3]}, "doubleSided": true},
    {"name": "kept", "alphaMode": "MASK", "alphaCutoff": 0.5, "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 0.6]}},
    {"name": "cut", "alphaMode": "MASK", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 0.4]}}],
  "buffers": [)" + buffer_json + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": )" + std::to_string(idx_count) +
         R"(, "type": "SCALAR"},
                {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}])" + extra + "}";
}

void expect_test_scene(const Scene& s) {
  // Kept: the BLEND, OPAQUE and kept MASK primitives of mesh 0, and mesh 1.
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.triangle_count(), 2u + 1 + 1 + 1);
  EXPECT_EQ(s.materials.at(s.objects[0].material).color, (Rgba8{255, 0, 0, 128}));  // BLEND
  EXPECT_EQ(s.materials.at(s.objects[1].material).color, (Rgba8{0, 255, 0, 255}));  // OPAQUE
  EXPECT_EQ(s.materials.at(s.objects[2].material).color, (Rgba8{0, 0, 255, 255}));  // MASK 0.6 >= 0.5
  EXPECT_EQ(s.materials.at(s.objects[3].material).color, (Rgba8{255, 255, 255, 255}));  // default
  // Node 1's world transform: translate(1, 2, 3) * scale(2): vertex (1, 1, 0) -> (3, 4, 3).
  const glm::vec4 w = s.objects[0].transform * glm::vec4(1, 1, 0, 1);
  EXPECT_EQ(glm::vec3(w), glm::vec3(3, 4, 3));
  const glm::vec4 m = s.objects[3].transform * glm::vec4(0, 1, 0, 1);
  EXPECT_EQ(glm::vec3(m), glm::vec3(10, 1, 0));
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), 2u);
  EXPECT_EQ(s.objects[0].mesh.positions[0], glm::vec3(0, 0, 0));
  EXPECT_CONTAINS(s.description, "1 point or line primitives ignored");
  EXPECT_CONTAINS(s.description, "1 MASK primitives below alphaCutoff dropped");
}

TEST_F(SceneFileTest, GltfTransformsMaterialsAndModes) {
  write("t.bin", test_buffer());
  expect_test_scene(load_scene_file(write("t.gltf", test_gltf(R"({"uri": "t.bin", "byteLength": 60})"))));
}

std::string make_glb(const std::string& json_in, const std::string& bin) {
  std::string json = json_in;
  while (json.size() % 4) json += ' ';
  auto u32 = [](uint32_t v) { std::string s(4, '\0'); std::memcpy(s.data(), &v, 4); return s; };
  std::string out = "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  out += u32(static_cast<uint32_t>(json.size())) + u32(0x4E4F534A) + json;
  out += u32(static_cast<uint32_t>(bin.size())) + u32(0x004E4942) + bin;
  return out;
}

TEST_F(SceneFileTest, GlbLoadsTheSameScene) {
  const std::string glb = make_glb(test_gltf(R"({"byteLength": 60})"), test_buffer());
  expect_test_scene(load_scene_file(write("t.glb", glb)));
}

TEST_F(SceneFileTest, GltfErrorsNameFilePlaceAndProblem) {
  write("t.bin", test_buffer());
  const std::string buf = R"({"uri": "t.bin", "byteLength": 60})";
  const std::string good = test_gltf(buf);
  std::string p = write("trunc.gltf", good.substr(0, good.size() / 2));
  EXPECT_CONTAINS(error_of(p), p + ": JSON: malformed: ");
  write("oob.bin", test_buffer(1.0f, 7));
  p = write("oob.gltf", test_gltf(R"({"uri": "oob.bin", "byteLength": 60})"));
  EXPECT_EQ(error_of(p), p + ": accessors[1]: element 5: index 7 out of range (4 vertices)");
  write("nan.bin", test_buffer(NAN));
  p = write("nan.gltf", test_gltf(R"({"uri": "nan.bin", "byteLength": 60})"));
  EXPECT_EQ(error_of(p), p + ": accessors[0]: element 1 is not finite");
  write("inf.bin", test_buffer(INFINITY));
  p = write("inf.gltf", test_gltf(R"({"uri": "inf.bin", "byteLength": 60})"));
  EXPECT_EQ(error_of(p), p + ": accessors[0]: element 1 is not finite");
  p = write("long.gltf", test_gltf(buf, 9));
  EXPECT_EQ(error_of(p), p + ": accessors[1]: 9 elements run past the end of bufferView 1");
  p = write("nobin.gltf", test_gltf(R"({"uri": "missing.bin", "byteLength": 60})"));
  EXPECT_EQ(error_of(p), p + ": buffers[0]: file '" + (dir_ / "missing.bin").string() + "' not found");
  p = write("short.gltf", test_gltf(R"({"uri": "t.bin", "byteLength": 64})"));
  EXPECT_EQ(error_of(p), p + ": buffers[0]: file '" + (dir_ / "t.bin").string() + "' has 60 bytes, byteLength says 64");
  std::string twice = good;  // node 1, a child of node 0, also a root
  twice.replace(twice.find("[0, 2]"), 6, "[0, 2, 1]");
  p = write("twice.gltf", twice);
  EXPECT_EQ(error_of(p), p + ": nodes[1]: node reached twice (a node has at most one parent and is no root besides)");
  p = write("lines.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 1}]}],
    "buffers": [{"uri": "t.bin", "byteLength": 60}],
    "bufferViews": [{"buffer": 0, "byteLength": 48}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"}]})");
  EXPECT_EQ(error_of(p), "scene '" + p + "': no triangles");
  p = write("cycle.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"children": [1]}, {"children": [0]}],
    "scenes": [{"nodes": [0]}]})");
  EXPECT_EQ(error_of(p), p + ": nodes[0]: cycle in the node hierarchy");
}

// A chain of `depth` nodes, the last with a one-triangle mesh; `extras` nested `nesting` deep.
std::string deep_gltf(int depth, int nesting) {
  std::string nodes;
  for (int i = 0; i + 1 < depth; ++i) nodes += "{\"children\": [" + std::to_string(i + 1) + "]}, ";
  nodes += R"({"mesh": 0})";
  return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [)" + nodes +
         R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"uri": "t.bin", "byteLength": 60}],
    "bufferViews": [{"buffer": 0, "byteLength": 48}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "extras": )" + std::string(size_t(nesting), '[') + std::string(size_t(nesting), ']') + "}";
}

TEST_F(SceneFileTest, DeepGltfKeepsTheStack) {
  write("t.bin", test_buffer());
  // The node walk keeps its own stack (a recursion this deep overflows under ASan); tinygltf
  // converts `extras` recursively, so JSON nesting is bounded.
  EXPECT_EQ(load_scene_file(write("deep.gltf", deep_gltf(20000, 63))).triangle_count(), 1u);
  std::string p = write("nested.gltf", deep_gltf(1, 64));
  EXPECT_EQ(error_of(p), p + ": JSON: nested deeper than 64 levels");
  p = write("nested.glb", make_glb(deep_gltf(1, 100000), ""));
  EXPECT_EQ(error_of(p), p + ": JSON chunk: nested deeper than 64 levels");
}

TEST_F(SceneFileTest, BytesInMemoryAndTheirFiles) {
  // The files a scene names come from the reader, by their name joined to the scene's directory.
  std::vector<std::string> asked;
  const SceneFileReader read = [&](const std::string& path, std::string& bytes) {
    asked.push_back(path);
    if (path == "mem/t.mtl") bytes = kMtl;
    else if (path == "mem/t.bin") bytes = test_buffer();
    else return FileRead::kMissing;
    return FileRead::kOk;
  };
  const Scene obj = load_scene_bytes("mem/t.obj", kObj, read);
  EXPECT_EQ(obj.triangle_count(), 3u);
  EXPECT_EQ(obj.materials.at(obj.objects[0].material).color, (Rgba8{255, 0, 0, 128}));
  EXPECT_EQ(asked, std::vector<std::string>{"mem/t.mtl"});
  expect_test_scene(load_scene_bytes("mem/t.gltf", test_gltf(R"({"uri": "t.bin", "byteLength": 60})"), read));
  expect_test_scene(load_scene_bytes("t.glb", make_glb(test_gltf(R"({"byteLength": 60})"), test_buffer()), read));
  try {
    load_scene_bytes("mem/u.obj", "mtllib u.mtl\n", read);
    ADD_FAILURE() << "loaded";
  } catch (const SceneFileError& e) {
    EXPECT_STREQ(e.what(), "mem/u.obj: line 1: material library 'mem/u.mtl' not found");
  }
}

TEST_F(SceneFileTest, DirectoriesAndOddFiles) {
  EXPECT_EQ(error_of(dir_.string()), dir_.string() + ": open: is a directory, not a scene file");
  fs::create_directory(dir_ / "d.obj");
  const std::string d = (dir_ / "d.obj").string();
  EXPECT_EQ(error_of(d), d + ": open: is a directory, not a scene file");
  // The MTL named by mtllib is a directory: not found, as a missing file.
  fs::create_directory(dir_ / "m.mtl");
  const std::string p = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(error_of(p), p + ": line 1: material library '" + (dir_ / "m.mtl").string() + "' not found");
}

TEST_F(SceneFileTest, ObjStatementsNotReadAreNotParsed) {
  // tinyobjloader gets only what zblend reads: its `vw` parser converts a huge joint id to int
  // (undefined behaviour, found by fuzz_obj). Old Mac line ends (a lone CR) end lines as there.
  const Scene s = load_scene_file(write("cr.obj", "v 0 0 0\rv 1 0 0\r\nv 0 1 0\rs 99999999999\r"
                                                  "vw 0 99999999999 0.5\rl 1 2\rp 1\rf 1 2 3\r"));
  EXPECT_EQ(s.triangle_count(), 1u);
  const std::string p = write("crline.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r");
  EXPECT_EQ(error_of(p), p + ": line 4: vertex index 4 out of range (1 to 3)");
}

TEST_F(SceneFileTest, DegenerateTrianglesLoad) {
  // Zero-area triangles are no error: the geometry stage drops them (docs/scenes.md).
  const Scene s = load_scene_file(write("z.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 1\n"));
  EXPECT_EQ(s.triangle_count(), 2u);
}

TEST_F(SceneFileTest, GlbErrorsNameTheByte) {
  const std::string glb = make_glb(test_gltf(R"({"byteLength": 60})"), test_buffer());
  std::string p = write("short.glb", glb.substr(0, glb.size() - 10));
  EXPECT_EQ(error_of(p), p + ": byte 8: GLB length " + std::to_string(glb.size()) + " but the file has " +
                             std::to_string(glb.size() - 10) + " bytes (truncated?)");
  p = write("tiny.glb", "glTF");
  EXPECT_EQ(error_of(p), p + ": byte 0: GLB header needs 12 bytes, file has 4");
  std::string bad = glb;
  bad[0] = 'X';
  p = write("magic.glb", bad);
  EXPECT_EQ(error_of(p), p + ": byte 0: not a GLB file (magic is not 'glTF')");
  bad = make_glb("{\"asset\": ", test_buffer());
  p = write("json.glb", bad);
  EXPECT_CONTAINS(error_of(p), p + ": JSON chunk: malformed: ");
}

TEST_F(SceneFileTest, EmptyBuffersAreErrors) {
  // A GLB buffer of byteLength 0 made tinygltf throw std::out_of_range (found by fuzz_gltf);
  // the schema's minimum of 1 is checked first, for buffers and buffer views.
  std::string p = write("empty.glb", make_glb(test_gltf(R"({"byteLength": 0})"), test_buffer()));
  EXPECT_EQ(error_of(p), p + ": buffers[0].byteLength: expected a positive integer, not number 0");
  std::string json = test_gltf(R"({"byteLength": 60})");
  json.replace(json.find(R"("byteLength": 12)"), 16, R"("byteLength": 0)");
  p = write("emptyview.glb", make_glb(json, test_buffer()));
  EXPECT_EQ(error_of(p), p + ": bufferViews[1].byteLength: expected a positive integer, not number 0");
}

// ---- the camera ------------------------------------------------------------------------------

// The error parse_camera_spec gives for `text`, or "parsed".
std::string camera_error(const std::string& text) {
  try {
    parse_camera_spec(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "parsed";
}

TEST(CameraSpec, ParsesStrictly) {
  const CameraSpec c = parse_camera_spec("eye=1,2,3,at=0,0.5,-1,fov=30");
  EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(c.at, glm::vec3(0, 0.5f, -1));
  EXPECT_EQ(c.fov_y_deg, 30.0f);
  EXPECT_EQ(parse_camera_spec("fov=60,at=0,0,0,eye=0,0,5").fov_y_deg, 60.0f);
  EXPECT_EQ(camera_error("eye=1,2,at=0,0,0,fov=30"), "field 'eye' needs 3 numbers, has 2");
  EXPECT_EQ(camera_error("eye=1,2,3,at=0,0,0"), "field 'fov' is missing");
  EXPECT_EQ(camera_error("eye=1,2,3,at=0,0,0,fov=abc"), "field 'fov': 'abc' is not a finite number");
  EXPECT_EQ(camera_error("eye=1,2,3,at=0,0,0,fov=180"), "field 'fov': 180 is out of range (1 to 179)");
  EXPECT_EQ(camera_error("eye=1,2,3,up=0,1,0,fov=30"), "field 'at' is missing");
  EXPECT_EQ(camera_error("eye=1,2,3,dir=0,1,0,fov=30"), "unknown field 'dir' (expected eye, at, fov, up)");
  EXPECT_EQ(camera_error("eye=1,2,3,at=1,2,3,fov=30"), "'eye' and 'at' are the same point");
  EXPECT_EQ(camera_error("eye=1,2,3,eye=1,2,3,fov=30"), "field 'eye' given twice");
  EXPECT_EQ(camera_error("1,2,3"), "'1' is not a field (expected eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z])");
}

TEST(CameraSpec, UpIsOptionalAndChecked) {
  EXPECT_FALSE(parse_camera_spec("eye=0,0,5,at=0,0,0,fov=30").up.has_value());
  const CameraSpec c = parse_camera_spec("up=1,0,0,eye=0,0,5,at=0,0,0,fov=30");
  ASSERT_TRUE(c.up.has_value());
  EXPECT_EQ(*c.up, glm::vec3(1, 0, 0));
  EXPECT_EQ(camera_error("eye=0,0,5,at=0,0,0,fov=30,up=0,0,0"), "field 'up' is the zero vector");
  EXPECT_EQ(camera_error("eye=0,0,5,at=0,0,0,fov=30,up=0,0,-2"),
            "'up' is parallel to the view direction (eye to at)");
  EXPECT_EQ(camera_error("eye=0,0,5,at=0,0,0,fov=30,up=1,0"), "field 'up' needs 3 numbers, has 2");
  EXPECT_EQ(camera_error("eye=0,0,5,at=0,0,0,fov=30,up=nan,1,0"), "field 'up': 'nan' is not a finite number");
  EXPECT_EQ(camera_error("eye=0,0,5,at=0,0,0,fov=30,up=0,1,0,up=0,1,0"), "field 'up' given twice");
}

TEST_F(SceneFileTest, AimedCameraFitsNearAndFar) {
  Scene s = load_scene_file(write("q.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n"));
  // Seen face-on, every vertex is 10 away along the view: near and far pad 0.1% of 10.
  aim_camera(s, parse_camera_spec("eye=0,0,10,at=0,0,0,fov=30"));
  EXPECT_EQ(s.camera.eye, glm::vec3(0, 0, 10));
  EXPECT_EQ(s.camera.up, glm::vec3(0, 1, 0));
  EXPECT_EQ(s.camera.fov_y_deg, 30.0f);
  EXPECT_NEAR(s.camera.near, 9.99f, 1e-5f);
  EXPECT_NEAR(s.camera.far, 10.01f, 1e-5f);
  // From the side, along +x: distances 9 to 11, padded by 1% of 2 and 0.1% of 11.
  aim_camera(s, parse_camera_spec("eye=-10,0,0,at=0,0,0,fov=30"));
  EXPECT_NEAR(s.camera.near, 9 - 0.031f, 1e-5f);
  EXPECT_NEAR(s.camera.far, 11 + 0.031f, 1e-5f);
  aim_camera(s, parse_camera_spec("eye=0,5,0,at=0,0,0,fov=30"));  // straight down: up is -z
  EXPECT_EQ(s.camera.up, glm::vec3(0, 0, -1));
  aim_camera(s, parse_camera_spec("eye=0,0,10,at=0,0,0,fov=30,up=3,0,0"));  // normalised
  EXPECT_EQ(s.camera.up, glm::vec3(1, 0, 0));
  EXPECT_THROW(aim_camera(s, parse_camera_spec("eye=0,0,10,at=0,0,20,fov=30")), std::invalid_argument);
  CameraSpec spec = parse_camera_spec("eye=0,0,10,at=0,0,0,fov=30");
  spec.up = glm::vec3(0, 0, 1);  // set directly: aim_camera checks it too
  EXPECT_THROW(aim_camera(s, spec), std::invalid_argument);
}

// Every entry of the camera's projection (and, with `view`, view) matrix is finite.
void expect_finite_camera(const Camera& c, bool view = true) {
  std::vector<glm::mat4> m = {c.projection(4.0f / 3.0f)};
  if (view) m.push_back(c.view());
  for (const glm::mat4& x : m)
    for (int i = 0; i < 16; ++i) EXPECT_TRUE(std::isfinite(glm::value_ptr(x)[i])) << i;
  EXPECT_GT(c.near, 0.0f);
  EXPECT_GT(c.far, c.near);
}

TEST_F(SceneFileTest, HugeCoordinatesKeepTheProjectionFinite) {
  // A triangle spanning +-1e20 in z = 0, seen face-on from 5 away: near and far hug it.
  Scene s = load_scene_file(write("big.obj", "v -1e20 -1e20 0\nv 1e20 -1e20 0\nv 0 1e20 0\nf 1 2 3\n"));
  // Fitted: near lowered so that 2 * far * near is a float. The view matrix is not finite
  // (glm::lookAtRH normalises eye - at, 3.7e20 long, in float: docs/scenes.md).
  expect_finite_camera(s.camera, false);
  aim_camera(s, parse_camera_spec("eye=0,0,5,at=0,0,0,fov=60"));
  expect_finite_camera(s.camera);
  EXPECT_LT(s.camera.near, 5.0f);
  EXPECT_GT(s.camera.far, 5.0f);
  // At the edge of the float range the fitted box's diagonal is no float: done in double.
  s = load_scene_file(write("edge.obj", "v -3e38 -3e38 0\nv 3e38 -3e38 0\nv 0 3e38 0\nf 1 2 3\n"));
  expect_finite_camera(s.camera, false);
  EXPECT_EQ(s.camera.far, 1e37f);
  aim_camera(s, parse_camera_spec("eye=0,0,1e10,at=0,0,0,fov=60"));
  expect_finite_camera(s.camera);
}

// ---- real files from Debian packages ---------------------------------------------------------

TEST(RealSceneFiles, Regr01HouseHasTransparentWindows) {
  const Scene s = load_scene_file("/usr/share/assimp/models/OBJ/regr01.obj");
  EXPECT_GT(s.triangle_count(), 1000u);
  bool transparent_used = false;
  for (const Object& o : s.objects) transparent_used |= s.materials.at(o.material).transparent();
  EXPECT_TRUE(transparent_used);
  bool windows = false;
  for (const Material& m : s.materials)
    if (m.name == "Windows") {
      windows = true;
      EXPECT_EQ(m.color.a, 128);  // d 0.5
    }
  EXPECT_TRUE(windows);
}

TEST(RealSceneFiles, ClearCoatGltfLoads) {
  const Scene s = load_scene_file("/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf");
  EXPECT_GT(s.triangle_count(), 0u);
  bool blend = false;
  for (const Material& m : s.materials) blend |= m.name == "Partial_Coating";  // alphaMode BLEND
  EXPECT_TRUE(blend);
}

TEST(RealSceneFiles, GlmarkBunny) {
  const Scene s = load_scene_file("/usr/share/glmark2/models/bunny.obj");
  EXPECT_EQ(s.triangle_count(), 69666u);
}

}  // namespace
}  // namespace zb
