// Rasterizer tests: fill rule, watertightness, depth interpolation, fragment order.
// Expected coverage comes from an independent brute-force test per pixel centre that states the
// top-left rule as a perturbation: a centre on an edge counts as the point (x + e, y + e^2) for
// an infinitesimal e > 0 (y down), i.e. it is inside when nudged right, or down for horizontal
// edges. Watertightness checks count hits, independently of any rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/geometry.h"
#include "raster/raster.h"
#include "scene/scene.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;

constexpr int32_t kOne = 256;   // one pixel in fixed point
constexpr int32_t kHalf = 128;  // pixel centre offset

ScreenVertex V(int64_t x, int64_t y, uint32_t z = 0, double ze = 0.0) {
  ScreenVertex v;
  v.x = static_cast<int32_t>(x);
  v.y = static_cast<int32_t>(y);
  v.z = z;
  v.z_exact = ze;
  return v;
}

ScreenTriangle T(ScreenVertex a, ScreenVertex b, ScreenVertex c, uint32_t prim = 0) {
  ScreenTriangle t;
  t.v[0] = a;
  t.v[1] = b;
  t.v[2] = c;
  t.prim = prim;
  t.color = Rgba8{1, 2, 3, 4};
  return t;
}

// Brute force: is the centre of pixel (px, py) inside the convex polygon `p` (any winding)?
bool centre_inside(const std::vector<ScreenVertex>& p, int px, int py) {
  const int64_t sx = int64_t{px} * kOne + kHalf, sy = int64_t{py} * kOne + kHalf;
  // Orientation from the shoelace sum.
  int64_t twice = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const ScreenVertex& a = p[i];
    const ScreenVertex& b = p[(i + 1) % p.size()];
    twice += int64_t{a.x} * b.y - int64_t{b.x} * a.y;
  }
  if (twice == 0) return false;
  const int64_t s = twice > 0 ? 1 : -1;
  for (size_t i = 0; i < p.size(); ++i) {
    const ScreenVertex& a = p[i];
    const ScreenVertex& b = p[(i + 1) % p.size()];
    // Cross product of (b - a) and (sample - a), sign-normalised so that inside is > 0, as a
    // polynomial in e for the sample (sx + e, sy + e^2).
    const int64_t c0 = s * ((int64_t{b.x} - a.x) * (sy - a.y) - (int64_t{b.y} - a.y) * (sx - a.x));
    const int64_t c1 = s * -(int64_t{b.y} - a.y);  // coefficient of e
    const int64_t c2 = s * (int64_t{b.x} - a.x);   // coefficient of e^2
    const bool positive = c0 > 0 || (c0 == 0 && (c1 > 0 || (c1 == 0 && c2 > 0)));
    if (!positive) return false;
  }
  return true;
}

bool centre_inside(const ScreenTriangle& t, int px, int py) {
  return centre_inside(std::vector<ScreenVertex>{t.v[0], t.v[1], t.v[2]}, px, py);
}

std::vector<Fragment> raster(const ScreenTriangle& t, const Viewport& vp,
                             std::vector<double>* ze = nullptr) {
  std::vector<Fragment> out;
  rasterize(t, vp, out, ze);
  return out;
}

// Hit count per pixel over all triangles.
std::vector<int> hits(const std::vector<ScreenTriangle>& tris, const Viewport& vp) {
  std::vector<int> count(size_t(vp.width) * vp.height, 0);
  std::vector<Fragment> frags;
  for (const ScreenTriangle& t : tris) rasterize(t, vp, frags);
  for (const Fragment& f : frags) {
    EXPECT_LT(f.x, vp.width);
    EXPECT_LT(f.y, vp.height);
    if (f.x < vp.width && f.y < vp.height) ++count[size_t(f.y) * vp.width + f.x];
  }
  return count;
}

// Every pixel whose centre is inside `outline` (brute force) is hit once, every other none.
void expect_exact_cover(const std::vector<ScreenTriangle>& tris,
                        const std::vector<ScreenVertex>& outline, const Viewport& vp) {
  const std::vector<int> count = hits(tris, vp);
  int bad = 0, inside = 0;
  for (int y = 0; y < vp.height; ++y) {
    for (int x = 0; x < vp.width; ++x) {
      const int want = centre_inside(outline, x, y) ? 1 : 0;
      inside += want;
      const int got = count[size_t(y) * vp.width + x];
      if (got != want && ++bad <= 10)
        ADD_FAILURE() << "pixel (" << x << "," << y << ") hit " << got << " times, want " << want;
    }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(inside, 0) << "the outline covered no pixel: the test checked nothing";
}

// Pixel-centre coordinate of pixel index i.
int64_t C(int64_t i) { return i * kOne + kHalf; }

TEST(Raster, SharedDiagonalEdgeHitOnce) {
  const Viewport vp = Viewport{24, 24};
  const int lo = 3, hi = 19;  // square corners at pixel centres; diagonals through centres
  const ScreenVertex tl = V(C(lo), C(lo)), tr = V(C(hi), C(lo)), br = V(C(hi), C(hi)),
                     bl = V(C(lo), C(hi));
  for (int variant = 0; variant < 8; ++variant) {
    SCOPED_TRACE(variant);
    std::vector<ScreenTriangle> tris;
    if (variant & 1) {  // main diagonal tl-br
      tris = {T(tl, tr, br, 0), T(tl, br, bl, 1)};
    } else {            // anti-diagonal tr-bl
      tris = {T(tl, tr, bl, 0), T(tr, br, bl, 1)};
    }
    if (variant & 2) std::swap(tris[0].v[1], tris[0].v[2]);
    if (variant & 4) std::swap(tris[1].v[1], tris[1].v[2]);
    const std::vector<int> count = hits(tris, vp);
    for (int y = 0; y < vp.height; ++y) {
      for (int x = 0; x < vp.width; ++x) {
        // Top and left sides of the square are in, right and bottom out.
        const int want = (x >= lo && x < hi && y >= lo && y < hi) ? 1 : 0;
        EXPECT_EQ(count[size_t(y) * vp.width + x], want) << "pixel " << x << "," << y;
      }
    }
    // The diagonal pixels belong to the triangle on their right (the edge is its left edge).
    std::vector<Fragment> f0 = raster(tris[0], vp), f1 = raster(tris[1], vp);
    for (int k = lo + 1; k < hi; ++k) {
      const int dx = (variant & 1) ? k : lo + hi - k;  // diagonal pixel in row k
      const uint32_t owner = (variant & 1) ? 0u : 1u;   // upper-right of tl-br is tri 0
      const std::vector<Fragment>& fs = owner == 0 ? f0 : f1;
      const bool found = std::any_of(fs.begin(), fs.end(), [&](const Fragment& f) {
        return f.x == dx && f.y == k;
      });
      EXPECT_TRUE(found) << "diagonal pixel " << dx << "," << k;
    }
  }
}

TEST(Raster, SharedVertexFanHitOnce) {
  const Viewport vp = Viewport{40, 40};
  const int64_t cx = C(20), cy = C(20);
  // Rings around the centre vertex, with edges from the centre that are horizontal, vertical,
  // diagonal through pixel centres, and arbitrary.
  const std::vector<std::vector<std::pair<int64_t, int64_t>>> rings = {
      {{8, 0}, {0, 8}, {-8, 0}, {0, -8}},
      {{8, 0}, {6, 6}, {0, 8}, {-6, 6}, {-8, 0}, {-6, -6}, {0, -8}, {6, -6}},
      {{7, 1}, {3, 9}, {-2, 5}, {-9, 1}, {-4, -7}, {5, -9}},
      {{10, 0}, {10, 3}, {-10, 0}, {-10, -2}},
  };
  for (size_t r = 0; r < rings.size(); ++r) {
    SCOPED_TRACE(r);
    for (int flip = 0; flip < 2; ++flip) {
      std::vector<ScreenTriangle> tris;
      const auto& ring = rings[r];
      for (size_t i = 0; i < ring.size(); ++i) {
        const auto& a = ring[i];
        const auto& b = ring[(i + 1) % ring.size()];
        ScreenTriangle t = T(V(cx, cy), V(cx + a.first * kOne, cy + a.second * kOne),
                             V(cx + b.first * kOne, cy + b.second * kOne), uint32_t(i));
        if (flip ^ (i & 1)) std::swap(t.v[1], t.v[2]);
        tris.push_back(t);
      }
      const std::vector<int> count = hits(tris, vp);
      EXPECT_EQ(count[20 * 40 + 20], 1) << "centre-vertex pixel";
      EXPECT_LE(*std::max_element(count.begin(), count.end()), 1);
    }
  }
}

// A parallelogram outline P + i/n U + j/n V, interior vertices jittered, each quad split along a
// random diagonal, random winding per triangle.
std::vector<ScreenTriangle> jittered_grid(std::mt19937& rng, ScreenVertex p, int64_t ux,
                                          int64_t uy, int64_t vx, int64_t vy, int n,
                                          int64_t jitter) {
  std::uniform_int_distribution<int64_t> j(-jitter, jitter);
  std::vector<ScreenVertex> g(size_t(n + 1) * (n + 1));
  for (int b = 0; b <= n; ++b) {
    for (int a = 0; a <= n; ++a) {
      int64_t x = p.x + (ux * a + vx * b) / n, y = p.y + (uy * a + vy * b) / n;
      if (a > 0 && a < n && b > 0 && b < n) {
        x += j(rng);
        y += j(rng);
      }
      g[size_t(b) * (n + 1) + a] = V(x, y);
    }
  }
  std::vector<ScreenTriangle> tris;
  auto at = [&](int a, int b) { return g[size_t(b) * (n + 1) + a]; };
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) {
      ScreenTriangle t0, t1;
      if (rng() & 1) {
        t0 = T(at(a, b), at(a + 1, b), at(a + 1, b + 1));
        t1 = T(at(a, b), at(a + 1, b + 1), at(a, b + 1));
      } else {
        t0 = T(at(a, b), at(a + 1, b), at(a, b + 1));
        t1 = T(at(a + 1, b), at(a + 1, b + 1), at(a, b + 1));
      }
      if (rng() & 1) std::swap(t0.v[1], t0.v[2]);
      if (rng() & 1) std::swap(t1.v[1], t1.v[2]);
      tris.push_back(t0);
      tris.push_back(t1);
    }
  }
  return tris;
}

TEST(Raster, JitteredGridMeshWatertight) {
  std::mt19937 rng(20240611u);
  const Viewport vp = Viewport{96, 80};
  struct Case { ScreenVertex p; int64_t ux, uy, vx, vy; int n; int64_t jitter; };
  const std::vector<Case> cases = {
      // Axis-aligned, outline between pixel centres.
      {V(5 * kOne, 4 * kOne), 80 * kOne, 0, 0, 70 * kOne, 10, 8 * kOne / 5},
      // Axis-aligned, outline through pixel centres (top-left rule on the boundary).
      {V(C(6), C(3)), 80 * kOne, 0, 0, 72 * kOne, 8, 9 * kOne / 5},
      // Slanted parallelogram, coordinates off the grid.
      {V(20 * kOne + 37, 2 * kOne + 11), 64 * kOne, 8 * kOne, -16 * kOne, 64 * kOne, 16,
       4 * kOne / 5},
      // Outline partly outside the viewport (scissor).
      {V(-10 * kOne + 5, -7 * kOne + 3), 120 * kOne, 0, 0, 100 * kOne, 12, 8 * kOne / 5},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    const Case& c = cases[i];
    const std::vector<ScreenTriangle> tris =
        jittered_grid(rng, c.p, c.ux, c.uy, c.vx, c.vy, c.n, c.jitter);
    const ScreenVertex p = c.p;
    const std::vector<ScreenVertex> outline = {
        p, V(p.x + c.ux, p.y + c.uy), V(p.x + c.ux + c.vx, p.y + c.uy + c.vy),
        V(p.x + c.vx, p.y + c.vy)};
    expect_exact_cover(tris, outline, vp);
  }
}

TEST(Raster, SliverStripWatertight) {
  // A strip between two horizontal lines zipped into long thin triangles: vertices a few
  // sub-pixels apart along lines 60 pixels apart.
  std::mt19937 rng(7u);
  const Viewport vp = Viewport{64, 72};
  for (int round = 0; round < 4; ++round) {
    SCOPED_TRACE(round);
    const int64_t x0 = 2 * kOne + 77, x1 = 61 * kOne + 3;
    const int64_t y_top = round < 2 ? 5 * kOne + 40 : C(5), y_bot = y_top + 60 * kOne + 19;
    std::uniform_int_distribution<int64_t> gap(1, round & 1 ? 9 : 600);
    auto line = [&]() {
      std::vector<int64_t> xs = {x0};
      while (xs.back() < x1) xs.push_back(std::min(x1, xs.back() + gap(rng)));
      return xs;
    };
    const std::vector<int64_t> top = line(), bot = line();
    std::vector<ScreenTriangle> tris;
    size_t i = 0, j = 0;
    while (i + 1 < top.size() || j + 1 < bot.size()) {
      const bool advance_top = j + 1 >= bot.size() || (i + 1 < top.size() && (rng() & 1));
      ScreenTriangle t = advance_top
                             ? T(V(top[i], y_top), V(top[i + 1], y_top), V(bot[j], y_bot))
                             : T(V(top[i], y_top), V(bot[j + 1], y_bot), V(bot[j], y_bot));
      if (rng() & 1) std::swap(t.v[1], t.v[2]);
      tris.push_back(t);
      if (advance_top) ++i; else ++j;
    }
    const std::vector<ScreenVertex> outline = {V(x0, y_top), V(x1, y_top), V(x1, y_bot),
                                               V(x0, y_bot)};
    expect_exact_cover(tris, outline, vp);
  }
}

TEST(Raster, MatchesBruteForceRule) {
  // Random triangles with vertices on a half-pixel grid (so edges and vertices often pass
  // exactly through pixel centres) and on the full sub-pixel grid.
  std::mt19937 rng(12345u);
  const Viewport vp = Viewport{32, 28};
  for (int n = 0; n < 3000; ++n) {
    const int64_t unit = (n % 3 == 0) ? 1 : (n % 3 == 1) ? kHalf : kOne / 4;
    std::uniform_int_distribution<int64_t> d(-4 * kOne / unit, 36 * kOne / unit);
    const ScreenTriangle t = T(V(d(rng) * unit, d(rng) * unit), V(d(rng) * unit, d(rng) * unit),
                               V(d(rng) * unit, d(rng) * unit));
    std::vector<Fragment> fr = raster(t, vp);
    std::vector<char> got(size_t(vp.width) * vp.height, 0);
    for (const Fragment& f : fr) got[size_t(f.y) * vp.width + f.x] += 1;
    for (int y = 0; y < vp.height; ++y)
      for (int x = 0; x < vp.width; ++x)
        ASSERT_EQ(got[size_t(y) * vp.width + x], centre_inside(t, x, y) ? 1 : 0)
            << "triangle " << n << " pixel " << x << "," << y;
  }
}

TEST(Raster, FragmentOrderRowsThenColumns) {
  std::mt19937 rng(99u);
  std::uniform_int_distribution<int64_t> d(-2 * kOne, 50 * kOne);
  const Viewport vp = Viewport{48, 48};
  for (int n = 0; n < 200; ++n) {
    ScreenTriangle t = T(V(d(rng), d(rng)), V(d(rng), d(rng)), V(d(rng), d(rng)), 77);
    t.front = n & 1;
    const std::vector<Fragment> fr = raster(t, vp);
    for (size_t i = 1; i < fr.size(); ++i) {
      const bool ordered = fr[i - 1].y < fr[i].y || (fr[i - 1].y == fr[i].y && fr[i - 1].x < fr[i].x);
      ASSERT_TRUE(ordered) << "triangle " << n << " fragment " << i;
    }
    for (const Fragment& f : fr) {
      ASSERT_EQ(f.prim, 77u);
      ASSERT_EQ(f.front, t.front);
      ASSERT_EQ(f.color, t.color);
    }
  }
}

TEST(Raster, ConstantDepthPlane) {
  const Viewport vp = Viewport{40, 40, 24};
  const uint32_t z = 0x5a5a5a;
  const ScreenTriangle t = T(V(3 * kOne + 17, 2 * kOne + 100, z, 0.37),
                             V(38 * kOne + 1, 9 * kOne + 3, z, 0.37),
                             V(11 * kOne + 200, 37 * kOne + 9, z, 0.37));
  std::vector<double> ze;
  const std::vector<Fragment> fr = raster(t, vp, &ze);
  ASSERT_FALSE(fr.empty());
  ASSERT_EQ(ze.size(), fr.size());
  for (size_t i = 0; i < fr.size(); ++i) {
    EXPECT_EQ(fr[i].z, z);
    EXPECT_NEAR(ze[i], 0.37, 1e-15);
  }
}

// Independent depth: plane through the three vertices, z(p) = z0 + (w1 (z1 - z0) + w2 (z2 - z0)) / A,
// rounded half up, with w1, w2 the sub-areas opposite v1 and v2, sign-normalised.
uint32_t expected_depth(const ScreenTriangle& t, int px, int py) {
  const i128 sx = int64_t{px} * kOne + kHalf, sy = int64_t{py} * kOne + kHalf;
  const ScreenVertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
  i128 area = i128(b.x - a.x) * (c.y - a.y) - i128(c.x - a.x) * (b.y - a.y);
  // Sub-area of (a, p, c) is v1's weight, of (a, b, p) is v2's weight.
  i128 w1 = (sx - a.x) * (c.y - a.y) - i128(c.x - a.x) * (sy - a.y);
  i128 w2 = i128(b.x - a.x) * (sy - a.y) - (sx - a.x) * i128(b.y - a.y);
  if (area < 0) {
    area = -area;
    w1 = -w1;
    w2 = -w2;
  }
  const i128 num = area * a.z + w1 * (i128(b.z) - a.z) + w2 * (i128(c.z) - a.z);
  // floor((num + floor(area / 2)) / area), num >= 0 inside.
  return static_cast<uint32_t>((num + area / 2) / area);
}

TEST(Raster, DepthInterpolationExact) {
  std::mt19937 rng(4242u);
  for (int bits : {16, 24, 32}) {
    SCOPED_TRACE(bits);
    const Viewport vp = Viewport{40, 36, bits};
    std::uniform_int_distribution<uint32_t> dz(0, depth_max(bits));
    for (int n = 0; n < 300; ++n) {
      // Small triangles, and huge ones (scissored) that need 128-bit products.
      const int64_t span = (n % 4 == 0) ? (int64_t{1} << 23) : 44 * kOne;
      std::uniform_int_distribution<int64_t> d(-span / 8, span);
      const ScreenTriangle t = T(V(d(rng), d(rng), dz(rng), 0.1), V(d(rng), d(rng), dz(rng), 0.2),
                                 V(d(rng), d(rng), dz(rng), 0.9));
      std::vector<double> ze;
      const std::vector<Fragment> fr = raster(t, vp, &ze);
      ASSERT_EQ(ze.size(), fr.size());
      const uint32_t zlo = std::min({t.v[0].z, t.v[1].z, t.v[2].z});
      const uint32_t zhi = std::max({t.v[0].z, t.v[1].z, t.v[2].z});
      for (size_t i = 0; i < fr.size(); ++i) {
        ASSERT_EQ(fr[i].z, expected_depth(t, fr[i].x, fr[i].y))
            << "triangle " << n << " pixel " << fr[i].x << "," << fr[i].y;
        ASSERT_GE(fr[i].z, zlo);
        ASSERT_LE(fr[i].z, zhi);
        ASSERT_GE(ze[i], 0.1 - 1e-12);
        ASSERT_LE(ze[i], 0.9 + 1e-12);
      }
    }
  }
}

TEST(Raster, VertexPixelGetsVertexDepth) {
  const Viewport vp = Viewport{32, 32, 24};
  // Vertex at the centre of pixel (5, 6), where a top edge and a left edge meet: covered.
  const uint32_t z0 = 1234567, z1 = 99, z2 = 16000000;
  for (int flip = 0; flip < 2; ++flip) {
    ScreenTriangle t = T(V(C(5), C(6), z0, 0.25), V(C(5) + 20 * kOne + 3, C(6), z1, 0.5),
                         V(C(5) + 7, C(6) + 17 * kOne, z2, 0.75));
    if (flip) std::swap(t.v[1], t.v[2]);
    std::vector<double> ze;
    const std::vector<Fragment> fr = raster(t, vp, &ze);
    ASSERT_FALSE(fr.empty());
    EXPECT_EQ(fr[0].x, 5);
    EXPECT_EQ(fr[0].y, 6);
    EXPECT_EQ(fr[0].z, z0);
    EXPECT_DOUBLE_EQ(ze[0], 0.25);
  }
}

TEST(Raster, ScissorAndDegenerateInputs) {
  const Viewport vp = Viewport{16, 12};
  // Mostly outside: only viewport pixels, matching the brute force.
  const ScreenTriangle big = T(V(-40 * kOne, -30 * kOne), V(10 * kOne + 3, 50 * kOne),
                               V(60 * kOne, -5 * kOne));
  const std::vector<Fragment> fr = raster(big, vp);
  size_t want = 0;
  for (int y = 0; y < vp.height; ++y)
    for (int x = 0; x < vp.width; ++x) want += centre_inside(big, x, y);
  EXPECT_EQ(fr.size(), want);
  for (const Fragment& f : fr) {
    EXPECT_LT(f.x, vp.width);
    EXPECT_LT(f.y, vp.height);
  }
  // Zero area, wholly outside, coordinates beyond the supported range: nothing, no crash.
  EXPECT_TRUE(raster(T(V(0, 0), V(5 * kOne, 5 * kOne), V(10 * kOne, 10 * kOne)), vp).empty());
  EXPECT_TRUE(raster(T(V(-9 * kOne, 0), V(-2 * kOne, 0), V(-5 * kOne, 8 * kOne)), vp).empty());
  EXPECT_TRUE(raster(T(V(INT32_MIN, 0), V(INT32_MAX, 0), V(0, INT32_MAX)), vp).empty());
}

// A large ground plane under and through the camera, tessellated, run through the geometry
// stage (near-plane and guard-band clipping) and rasterized.
Scene ground_scene(glm::vec3 eye, glm::vec3 at, int n, float half) {
  Scene s;
  s.materials.push_back(Material{"ground", Rgba8{120, 160, 90, 255}});
  Object o;
  o.name = "ground";
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      o.mesh.positions.push_back(glm::vec3(-half + 2 * half * i / n, 0.0f, -half + 2 * half * j / n));
      o.mesh.normals.push_back(glm::vec3(0, 1, 0));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if ((i + j) & 1) {
        o.mesh.triangles.push_back({a, c, b});
        o.mesh.triangles.push_back({b, c, d});
      } else {
        o.mesh.triangles.push_back({a, c, d});
        o.mesh.triangles.push_back({a, d, b});
      }
    }
  }
  o.transform = glm::mat4(glm::mat3(glm::vec3(0.96f, 0.0f, 0.28f), glm::vec3(0, 1, 0),
                                    glm::vec3(-0.28f, 0.0f, 0.96f)));
  s.objects.push_back(o);
  s.camera.eye = eye;
  s.camera.at = at;
  s.camera.near = 0.1f;
  s.camera.far = 500.0f;
  return s;
}

TEST(Raster, NearClippedGroundPlaneWatertight) {
  struct Case { glm::vec3 eye, at; bool bottom_full; };
  const std::vector<Case> cases = {
      {{0.3f, 1.0f, 0.2f}, {2.0f, 0.0f, -5.0f}, true},     // looking down at the ground
      {{0.0f, 0.02f, 0.0f}, {0.5f, 0.02f, -10.0f}, false},  // eye just above: near cut visible
      {{1.0f, 3.0f, 1.0f}, {1.0f, 0.0f, 0.5f}, true},       // looking almost straight down
  };
  const Viewport vp = Viewport{160, 120};
  for (size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(k);
    const Scene s = ground_scene(cases[k].eye, cases[k].at, 16, 40.0f);
    const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
    ASSERT_FALSE(tris.empty());
    const std::vector<int> count = hits(tris, vp);
    EXPECT_LE(*std::max_element(count.begin(), count.end()), 1) << "a pixel was hit twice";
    // The projection of the (convex) clipped plane is convex: every row's hits form one run,
    // and the rows with hits are consecutive.
    int first_row = -1, last_row = -1, holes = 0;
    for (int y = 0; y < vp.height; ++y) {
      int lo = vp.width, hi = -1, n = 0;
      for (int x = 0; x < vp.width; ++x) {
        if (count[size_t(y) * vp.width + x]) {
          lo = std::min(lo, x);
          hi = std::max(hi, x);
          ++n;
        }
      }
      if (n == 0) continue;
      if (first_row < 0) first_row = y;
      EXPECT_TRUE(last_row < 0 || last_row == y - 1) << "empty rows inside the region at " << y;
      last_row = y;
      if (n != hi - lo + 1 && ++holes <= 5) ADD_FAILURE() << "hole in row " << y;
    }
    EXPECT_EQ(holes, 0);
    ASSERT_GE(first_row, 0);
    if (cases[k].bottom_full) {
      EXPECT_EQ(last_row, vp.height - 1);
      for (int x = 0; x < vp.width; ++x) EXPECT_EQ(count[size_t(vp.height - 1) * vp.width + x], 1);
    } else {
      EXPECT_LT(last_row, vp.height - 1) << "the near-plane cut should be on screen";
      EXPECT_GT(last_row, vp.height / 2);
    }
  }
}

}  // namespace
}  // namespace zb
