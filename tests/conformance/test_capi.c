/* test_capi: the golden model's C API, from C99 (so zb_golden.h is proved to be C).
 * First every error path: the status, one line naming the call, and nothing changed. Then
 * exported tests replayed through the API, read straight from their stream.hex (a decoder of
 * the format independent of the exporter's encoder): every push's reported writes must be what
 * the planes then hold, every pass's counters must add up, and the final planes must equal the
 * test's expect files, which the exporter computed with GoldenRop. Each test again through
 * zb_golden_replay_file (the library's own decoder) and zb_golden_read_plane: the same planes.
 * The stream reader's errors: hand-made streams, each wrong in one way, and a suite's stream
 * cut short.
 *
 * Usage: test_capi SUITE [TEST...]   (no TEST: every test directory of SUITE) */
#define _POSIX_C_SOURCE 200809L /* opendir, mkstemp */

#include <dirent.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zb_golden.h"

static int failures;

#define CHECK(cond, ...)                                             \
  do {                                                               \
    if (!(cond)) {                                                   \
      ++failures;                                                    \
      fprintf(stderr, "test_capi: line %d: FAIL: ", __LINE__);       \
      fprintf(stderr, __VA_ARGS__);                                  \
      fputc('\n', stderr);                                           \
    }                                                                \
  } while (0)

/* The call returned `want`, and the error it left (on g, or the thread's for NULL) is one line
 * starting with the call's name. The lines are printed: the log shows what users read. */
static void expect_error(int line, int got, int want, const zb_golden* g, const char* call) {
  const char* e = zb_golden_last_error(g);
  if (got != want || e == NULL || strncmp(e, call, strlen(call)) != 0 || strchr(e, '\n') != NULL ||
      strlen(e) <= strlen(call) + 2) {
    ++failures;
    fprintf(stderr, "test_capi: line %d: FAIL: %s: status %d (want %d), error '%s'\n", line, call,
            got, want, e ? e : "(null)");
    return;
  }
  printf("error path, line %d: %s\n", line, e);
}
#define EXPECT_ERROR(call_expr, want, g, name) expect_error(__LINE__, (call_expr), (want), (g), (name))

static uint32_t read_plane(zb_golden* g, int plane, int x, int y) {
  uint32_t v = 0xdeadbeefu;
  CHECK(zb_golden_read(g, plane, x, y, &v) == ZB_OK, "read plane %d (%d, %d): %s", plane, x, y,
        zb_golden_last_error(g));
  return v;
}

/* A coverage pass: depth test on, less, depth write, blend 3, every channel. */
#define STATE_COVERAGE (1u | 1u << 1 | 1u << 4 | 3u << 5 | 15u << 8)

static void test_errors(void) {
  zb_golden* g = NULL;
  uint32_t wrote = 0, v = 0;
  uint64_t in = 0;

  /* create: the widths and the out pointer; the error is the thread's. */
  EXPECT_ERROR(zb_golden_create(NULL, 8, 4, 24, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 0, 4, 24, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  CHECK(g == NULL, "a failed create leaves the handle NULL");
  EXPECT_ERROR(zb_golden_create(&g, 8193, 4, 24, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, -1, 24, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, 4, 7, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, 4, 33, 16, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, 4, 24, 0, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, 4, 24, 3, 0), ZB_EARG, NULL, "zb_golden_create");
  EXPECT_ERROR(zb_golden_create(&g, 8, 4, 24, 32, 0), ZB_EARG, NULL, "zb_golden_create");

  /* A NULL handle, on every call that takes one. */
  EXPECT_ERROR(zb_golden_begin_pass(NULL, STATE_COVERAGE), ZB_EHANDLE, NULL, "zb_golden_begin_pass");
  EXPECT_ERROR(zb_golden_push(NULL, 0, 0, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EHANDLE, NULL,
               "zb_golden_push");
  EXPECT_ERROR(zb_golden_end_pass(NULL, &in, NULL, NULL, NULL, NULL, NULL), ZB_EHANDLE, NULL,
               "zb_golden_end_pass");
  EXPECT_ERROR(zb_golden_frame_op(NULL, ZB_OP_CLEAR_COLOR, 0, 0), ZB_EHANDLE, NULL,
               "zb_golden_frame_op");
  EXPECT_ERROR(zb_golden_read(NULL, ZB_PLANE_COLOR, 0, 0, &v), ZB_EHANDLE, NULL, "zb_golden_read");
  EXPECT_ERROR(zb_golden_set_wboit(NULL, 16, 8, 4), ZB_EHANDLE, NULL, "zb_golden_set_wboit");
  zb_golden_destroy(NULL);

  /* An 8x4 frame, 16-bit depth, 4 samples. */
  CHECK(zb_golden_create(&g, 8, 4, 16, 4, 0x11223344u) == ZB_OK && g != NULL, "create: %s",
        zb_golden_last_error(NULL));
  if (g == NULL) return;
  CHECK(strcmp(zb_golden_last_error(NULL), "") == 0, "a good create clears the thread's error");

  /* The accumulation widths: out of range; then good, before the first pass. */
  EXPECT_ERROR(zb_golden_set_wboit(g, 7, 8, 4), ZB_EARG, g, "zb_golden_set_wboit");
  EXPECT_ERROR(zb_golden_set_wboit(g, 16, 17, 4), ZB_EARG, g, "zb_golden_set_wboit");
  EXPECT_ERROR(zb_golden_set_wboit(g, 16, 8, -1), ZB_EARG, g, "zb_golden_set_wboit");
  CHECK(zb_golden_set_wboit(g, 12, 10, 4) == ZB_OK, "set_wboit: %s", zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_REVEAL, 7, 3) == 1023u && read_plane(g, ZB_PLANE_ACC_A, 7, 3) == 0,
        "a 10-bit revealage clears to 1023, the accumulation to 0");
  CHECK(read_plane(g, ZB_PLANE_COLOR, 7, 3) == 0x11223344u, "set_wboit keeps the clear colour");

  /* Calls out of order. */
  EXPECT_ERROR(zb_golden_push(g, 0, 0, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EORDER, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_end_pass(g, &in, NULL, NULL, NULL, NULL, NULL), ZB_EORDER, g, "zb_golden_end_pass");

  /* Bad state words: bits above 15, blend code 7. */
  EXPECT_ERROR(zb_golden_begin_pass(g, 1u << 16), ZB_EARG, g, "zb_golden_begin_pass");
  EXPECT_ERROR(zb_golden_begin_pass(g, 7u << 5), ZB_EARG, g, "zb_golden_begin_pass");
  EXPECT_ERROR(zb_golden_begin_pass(g, 0xffffffffu), ZB_EARG, g, "zb_golden_begin_pass");
  CHECK(zb_golden_begin_pass(g, STATE_COVERAGE) == ZB_OK, "begin: %s", zb_golden_last_error(g));
  CHECK(strcmp(zb_golden_last_error(g), "") == 0, "a good call clears the handle's error");
  EXPECT_ERROR(zb_golden_begin_pass(g, STATE_COVERAGE), ZB_EORDER, g, "zb_golden_begin_pass");

  /* Bad fragments: pixel outside the frame, depth above 16 bits, coverage outside 0..4. */
  EXPECT_ERROR(zb_golden_push(g, -1, 0, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 8, 0, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 0, -1, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 0, 4, 0, 0, 0, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 0, 0, 0x10000u, 0, 0, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 0, 0, 0, 0, -1, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  EXPECT_ERROR(zb_golden_push(g, 0, 0, 0, 0, 5, &wrote, NULL, NULL, NULL), ZB_EARG, g, "zb_golden_push");
  CHECK(wrote == 0, "a failed push reports no writes");
  EXPECT_ERROR(zb_golden_frame_op(g, ZB_OP_CLEAR_COLOR, 0, 0), ZB_EORDER, g, "zb_golden_frame_op");
  EXPECT_ERROR(zb_golden_set_wboit(g, 16, 8, 4), ZB_EORDER, g, "zb_golden_set_wboit");

  /* The failures changed nothing; a good push with every output NULL is counted. */
  CHECK(read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0x11223344u, "colour after failed calls");
  CHECK(read_plane(g, ZB_PLANE_COVERAGE, 0, 0) == 0, "coverage after failed calls");
  CHECK(zb_golden_push(g, 0, 0, 100, 0xff0000ffu, 4, NULL, NULL, NULL, NULL) == ZB_OK, "push: %s",
        zb_golden_last_error(g));
  CHECK(zb_golden_end_pass(g, &in, NULL, NULL, NULL, NULL, NULL) == ZB_OK && in == 1,
        "end_pass: %" PRIu64 " fragments in, want 1 (%s)", in, zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_COVERAGE, 0, 0) == 4 && read_plane(g, ZB_PLANE_DEPTH, 0, 0) == 100,
        "a full-coverage nearer fragment sets coverage 4 and depth 100");

  /* Frame operations and reads. */
  EXPECT_ERROR(zb_golden_frame_op(g, -1, 0, 0), ZB_EARG, g, "zb_golden_frame_op");
  EXPECT_ERROR(zb_golden_frame_op(g, 6, 0, 0), ZB_EARG, g, "zb_golden_frame_op");
  EXPECT_ERROR(zb_golden_read(g, -1, 0, 0, &v), ZB_EARG, g, "zb_golden_read");
  EXPECT_ERROR(zb_golden_read(g, 9, 0, 0, &v), ZB_EARG, g, "zb_golden_read");
  EXPECT_ERROR(zb_golden_read(g, ZB_PLANE_PEEL, 8, 0, &v), ZB_EARG, g, "zb_golden_read");
  EXPECT_ERROR(zb_golden_read(g, ZB_PLANE_PEEL, 0, 4, &v), ZB_EARG, g, "zb_golden_read");
  EXPECT_ERROR(zb_golden_read(g, ZB_PLANE_COLOR, 0, 0, NULL), ZB_EARG, g, "zb_golden_read");
  CHECK(zb_golden_frame_op(g, ZB_OP_CLEAR_DEPTH, 0, 0xffffffffu) == ZB_OK, "clear depth: %s",
        zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_DEPTH, 7, 3) == 0xffffu, "a depth clear is clamped to ZMAX");
  CHECK(strcmp(zb_golden_last_error(g), "") == 0, "the error is cleared by a good call");
  zb_golden_destroy(g);
}

/* An accumulate pass, 16-bit depth, widths 16, 8, 4, worked by hand from datapath.md "7.
 * Accumulate blend": z = 0 gives u = 255 and F = 255^3 >> 20 = 15; rgba (200, 100, 0, 255):
 * w = 255 * 15 = 3825, terms p * w >> 8 (S = 4 + 20 - 16): R 2988, G 1494, B 0, A 3810;
 * revealage 255 * (1 - 1) = 0. The resolve: avg_R = (2988 * 255 + 1905) / 3810 = 200,
 * avg_G = 100, avg_B = 0, avg_A = 255, and with r = 0 the colour is the average. */
static void test_accumulate(void) {
  zb_golden* g = NULL;
  uint32_t wrote = 0;
  const uint32_t state = 5u << 5 | 15u << 8; /* no depth test, accumulate, every channel */
  CHECK(zb_golden_create(&g, 4, 2, 16, 16, 0xff808080u) == ZB_OK, "create: %s",
        zb_golden_last_error(NULL));
  if (g == NULL) return;
  CHECK(zb_golden_set_wboit(g, 16, 8, 4) == ZB_OK && zb_golden_begin_pass(g, state) == ZB_OK,
        "begin: %s", zb_golden_last_error(g));
  CHECK(zb_golden_push(g, 1, 1, 0, 0xff0064c8u, 16, &wrote, NULL, NULL, NULL) == ZB_OK,
        "push: %s", zb_golden_last_error(g));
  CHECK(wrote == ZB_WROTE_ACCUM, "an accumulate fragment writes the word only (wrote %u)", wrote);
  CHECK(read_plane(g, ZB_PLANE_ACC_R, 1, 1) == 2988u && read_plane(g, ZB_PLANE_ACC_G, 1, 1) == 1494u &&
            read_plane(g, ZB_PLANE_ACC_B, 1, 1) == 0 && read_plane(g, ZB_PLANE_ACC_A, 1, 1) == 3810u &&
            read_plane(g, ZB_PLANE_REVEAL, 1, 1) == 0,
        "accumulation (%u, %u, %u, %u) revealage %u, want (2988, 1494, 0, 3810) 0",
        read_plane(g, ZB_PLANE_ACC_R, 1, 1), read_plane(g, ZB_PLANE_ACC_G, 1, 1),
        read_plane(g, ZB_PLANE_ACC_B, 1, 1), read_plane(g, ZB_PLANE_ACC_A, 1, 1),
        read_plane(g, ZB_PLANE_REVEAL, 1, 1));
  EXPECT_ERROR(zb_golden_frame_op(g, ZB_OP_RESOLVE_WBOIT, 0, 0), ZB_EORDER, g, "zb_golden_frame_op");
  CHECK(zb_golden_end_pass(g, NULL, NULL, NULL, NULL, NULL, NULL) == ZB_OK &&
            zb_golden_frame_op(g, ZB_OP_RESOLVE_WBOIT, 0, 0) == ZB_OK,
        "resolve: %s", zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_COLOR, 1, 1) == 0xff0064c8u, "resolved %08x, want ff0064c8",
        read_plane(g, ZB_PLANE_COLOR, 1, 1));
  CHECK(read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0xff808080u, "an untouched pixel keeps its colour");
  zb_golden_destroy(g);
}

/* A declared arithmetic (datapath.md "Declared arithmetic"), worked by hand: clear colour
 * (34, 51, 102, 0), an alpha fragment (0, 0, 0, 64), so d * 191 on R, G, B: 6494, 9741, 19482.
 * zblend's m: (6494 + 25 + 128) >> 8 = 25, (9741 + 38 + 128) >> 8 = 38, (19482 + 76 + 128) >> 8
 * = 76; sum-ceil256: (6494 + 255) >> 8 = 26, 39, 77. Alpha 64 * 64 = 4096: 16 under both. */
static void test_arithmetic(void) {
  zb_golden* g = NULL;
  uint32_t rgba = 0;
  const uint32_t state = 1u << 5 | 15u << 8; /* no depth test, alpha blend, every channel */
  CHECK(zb_golden_create(&g, 2, 1, 16, 4, 0x00663322u) == ZB_OK, "create: %s",
        zb_golden_last_error(NULL));
  if (g == NULL) return;
  EXPECT_ERROR(zb_golden_set_arithmetic(g, "sum-ceil"), ZB_EARG, g, "zb_golden_set_arithmetic");
  EXPECT_ERROR(zb_golden_set_arithmetic(g, NULL), ZB_EARG, g, "zb_golden_set_arithmetic");
  EXPECT_ERROR(zb_golden_set_arithmetic(NULL, "zblend"), ZB_EHANDLE, NULL, "zb_golden_set_arithmetic");
  CHECK(zb_golden_begin_pass(g, state) == ZB_OK &&
            zb_golden_push(g, 0, 0, 0, 0x40000000u, 0, NULL, NULL, NULL, &rgba) == ZB_OK,
        "push: %s", zb_golden_last_error(g));
  CHECK(rgba == 0x104c2619u, "zblend's arithmetic: %08x, want 104c2619", rgba);
  EXPECT_ERROR(zb_golden_set_arithmetic(g, "sum-ceil256"), ZB_EORDER, g, "zb_golden_set_arithmetic");
  CHECK(zb_golden_end_pass(g, NULL, NULL, NULL, NULL, NULL, NULL) == ZB_OK &&
            zb_golden_set_arithmetic(g, "sum-ceil256") == ZB_OK && zb_golden_begin_pass(g, state) == ZB_OK &&
            zb_golden_push(g, 1, 0, 0, 0x40000000u, 0, NULL, NULL, NULL, &rgba) == ZB_OK,
        "sum-ceil256: %s", zb_golden_last_error(g));
  CHECK(rgba == 0x104d271au, "sum-ceil256: %08x, want 104d271a", rgba);
  CHECK(read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0x104c2619u, "the first pass's pixel kept");
  zb_golden_destroy(g);
}

/* A layers pass (mlab-K, K = 2), 16-bit depth, worked by hand from datapath.md "8. Layers":
 * rgba (255, 0, 0, 128) at z 100 is the layer p = (m(255, 128), 0, 0) = (128, 0, 0), A 128;
 * (0, 0, 255, 64) at z 50 goes before it as (0, 0, 64), A 64. The resolve: acc = (0, 0, 64, 64),
 * then t = 191: R 0 + m(128, 191) = 96, A 64 + m(128, 191) = 160; over (64, 64, 64, 255) with
 * 255 - 160 = 95: m(64, 95) = 24 on R, G, B and m(255, 95) = 95 on A: (120, 24, 88, 255). */
static void test_layers(void) {
  zb_golden* g = NULL;
  uint32_t wrote = 0, rgba = 1;
  const uint32_t state = 6u << 5 | 15u << 8 | 1u << 13; /* no depth test, layers, K = 2 */
  CHECK(zb_golden_create(&g, 2, 1, 16, 4, 0xff404040u) == ZB_OK, "create: %s",
        zb_golden_last_error(NULL));
  if (g == NULL) return;
  CHECK(zb_golden_begin_pass(g, state) == ZB_OK, "begin: %s", zb_golden_last_error(g));
  CHECK(zb_golden_push(g, 0, 0, 100, 0x800000ffu, 0, &wrote, NULL, NULL, &rgba) == ZB_OK &&
            wrote == ZB_WROTE_LAYERS && rgba == 0,
        "a layers fragment writes the layers only (wrote %u): %s", wrote, zb_golden_last_error(g));
  CHECK(zb_golden_push(g, 0, 0, 50, 0x40ff0000u, 0, &wrote, NULL, NULL, NULL) == ZB_OK &&
            wrote == ZB_WROTE_LAYERS,
        "push: wrote %u: %s", wrote, zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0xff404040u, "the colour waits for the resolve");
  CHECK(zb_golden_end_pass(g, NULL, NULL, NULL, NULL, NULL, NULL) == ZB_OK &&
            zb_golden_frame_op(g, ZB_OP_RESOLVE_LAYERS, 0, 0) == ZB_OK,
        "resolve: %s", zb_golden_last_error(g));
  CHECK(read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0xff581878u, "resolved %08x, want ff581878",
        read_plane(g, ZB_PLANE_COLOR, 0, 0));
  CHECK(read_plane(g, ZB_PLANE_COLOR, 1, 0) == 0xff404040u, "a pixel with no layer keeps its colour");
  CHECK(zb_golden_frame_op(g, ZB_OP_RESOLVE_LAYERS, 0, 0) == ZB_OK &&
            read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0xff581878u,
        "the resolve empties the layers: a second one changes nothing (%08x)",
        read_plane(g, ZB_PLANE_COLOR, 0, 0));
  zb_golden_destroy(g);
}

/* A 128-bit stream word as four 32-bit lanes, w[0] = bits [31:0]. */
typedef struct {
  uint32_t w[4];
} word128;

static int read_word(FILE* f, word128* out) {
  char line[80];
  int i;
  if (!fgets(line, sizeof line, f) || strlen(line) != 33 || line[32] != '\n') return 0;
  for (i = 0; i < 4; ++i) {
    char lane[9];
    char* end = NULL;
    memcpy(lane, line + 8 * i, 8);
    lane[8] = '\0';
    out->w[3 - i] = (uint32_t)strtoul(lane, &end, 16);
    if (end != lane + 8) return 0;
  }
  return 1;
}

static const char* const kPlaneNames[5] = {"color", "depth", "coverage", "peel", "accum"};
#define N_READ_PLANES 9 /* ZB_PLANE_COLOR .. ZB_PLANE_REVEAL */

/* One push, held to the planes: a plane it reports written holds the value it reports, the
 * others (and the peel plane always) are unchanged; the accumulation word changes only when
 * reported written. */
static void push_checked(zb_golden* g, const char* test, uint64_t n, int x, int y, uint32_t z,
                         uint32_t rgba, int coverage) {
  uint32_t before[N_READ_PLANES], after[N_READ_PLANES], wrote = 0, wd = 0, wc = 0, wrgba = 0;
  int p, accum_same = 1;
  for (p = 0; p < N_READ_PLANES; ++p) before[p] = read_plane(g, p, x, y);
  if (zb_golden_push(g, x, y, z, rgba, coverage, &wrote, &wd, &wc, &wrgba) != ZB_OK) {
    CHECK(0, "%s: word %" PRIu64 ": push: %s", test, n, zb_golden_last_error(g));
    return;
  }
  for (p = 0; p < N_READ_PLANES; ++p) after[p] = read_plane(g, p, x, y);
  for (p = ZB_PLANE_ACC_R; p < N_READ_PLANES; ++p) accum_same &= after[p] == before[p];
  CHECK((wrote & ZB_WROTE_COLOR) ? after[0] == wrgba : (after[0] == before[0] && wrgba == 0),
        "%s: word %" PRIu64 ": colour of (%d, %d): reported %08x (wrote %u), plane %08x", test, n,
        x, y, wrgba, wrote, after[0]);
  CHECK((wrote & ZB_WROTE_DEPTH) ? after[1] == wd : (after[1] == before[1] && wd == 0),
        "%s: word %" PRIu64 ": depth of (%d, %d): reported %x (wrote %u), plane %x", test, n, x,
        y, wd, wrote, after[1]);
  CHECK((wrote & ZB_WROTE_COVERAGE) ? after[2] == wc : (after[2] == before[2] && wc == 0),
        "%s: word %" PRIu64 ": coverage of (%d, %d): reported %u (wrote %u), plane %u", test, n,
        x, y, wc, wrote, after[2]);
  CHECK(after[3] == before[3], "%s: word %" PRIu64 ": a push changed the peel plane", test, n);
  CHECK((wrote & ZB_WROTE_ACCUM) || accum_same,
        "%s: word %" PRIu64 ": the accumulation word of (%d, %d) changed, not reported", test, n, x, y);
}

/* Bits [lo, lo + width) of a hex word (width <= 32), the lowest digit last. */
static uint32_t hex_field(const char* hex, int lo, int width) {
  const int digits = (int)strlen(hex);
  uint32_t v = 0;
  int b;
  for (b = lo + width - 1; b >= lo; --b) {
    const int d = digits - 1 - b / 4;
    const char c = d >= 0 ? hex[d] : '0';
    const int nibble = c <= '9' ? c - '0' : c - 'a' + 10;
    v = v << 1 | (uint32_t)((nibble >> (b % 4)) & 1);
  }
  return v;
}

/* The nine planes of a frame (ZB_PLANE_COLOR .. ZB_PLANE_REVEAL), width * height values each,
 * row-major from row 0. */
typedef struct {
  int width, height, acc_bits, rev_bits;
  uint32_t* v[N_READ_PLANES];
} frame_planes;

static int planes_alloc(frame_planes* f, int width, int height, int acc_bits, int rev_bits) {
  int p, ok = 1;
  f->width = width;
  f->height = height;
  f->acc_bits = acc_bits;
  f->rev_bits = rev_bits;
  for (p = 0; p < N_READ_PLANES; ++p) {
    f->v[p] = (uint32_t*)calloc((size_t)width * (size_t)height, sizeof(uint32_t));
    ok &= f->v[p] != NULL;
  }
  CHECK(ok, "out of memory for a %dx%d frame's planes", width, height);
  return ok;
}

static void planes_free(frame_planes* f) {
  int p;
  for (p = 0; p < N_READ_PLANES; ++p) free(f->v[p]);
}

/* Every pixel of every plane through zb_golden_read. */
static void planes_by_pixel(zb_golden* g, frame_planes* f) {
  int p, x, y;
  for (p = 0; p < N_READ_PLANES; ++p)
    for (y = 0; y < f->height; ++y)
      for (x = 0; x < f->width; ++x)
        f->v[p][(size_t)y * (size_t)f->width + (size_t)x] = read_plane(g, p, x, y);
}

/* The planes against SUITE/TEST/expect.<plane>.hex: the first differing pixel and a count. */
static void compare_expect(const char* suite, const char* test, const frame_planes* f) {
  char path[4096];
  FILE* file;
  int p;
  for (p = 0; p < 5; ++p) {
    int x, y, differ = 0;
    snprintf(path, sizeof path, "%s/%s/expect.%s.hex", suite, test, kPlaneNames[p]);
    file = fopen(path, "r");
    CHECK(file != NULL, "cannot open %s", path);
    if (!file) continue;
    for (y = 0; y < f->height; ++y)
      for (x = 0; x < f->width; ++x) {
        const size_t i = (size_t)y * (size_t)f->width + (size_t)x;
        char hex[40];
        int k, same = 1;
        if (fscanf(file, "%39s", hex) != 1) {
          CHECK(0, "%s: too short", path);
          x = f->width, y = f->height;
          break;
        }
        if (p < 4) { /* one word */
          same = f->v[p][i] == hex_field(hex, 0, 32);
        } else { /* the accumulation word: acc R, G, B, A, then r, from bit 0 */
          for (k = 0; k < 4; ++k)
            same &= f->v[ZB_PLANE_ACC_R + k][i] == hex_field(hex, k * f->acc_bits, f->acc_bits);
          same &= f->v[ZB_PLANE_REVEAL][i] == hex_field(hex, 4 * f->acc_bits, f->rev_bits);
        }
        if (!same && differ++ == 0)
          CHECK(0, "%s: %s pixel (%d, %d): expect file %s, C API differs", test, kPlaneNames[p],
                x, y, hex);
      }
    CHECK(differ == 0, "%s: %d %s pixels differ", test, differ, kPlaneNames[p]);
    fclose(file);
  }
}

/* Replays SUITE/TEST/stream.hex through the API and compares the planes with the expect files. */
static void replay(const char* suite, const char* test) {
  char path[4096];
  FILE* f;
  word128 word;
  zb_golden* g = NULL;
  uint64_t count, n, pass_fragments = 0, fragments = 0;
  int width = 0, height = 0, ended = 0, in_pass = 0, acc_bits = 0, rev_bits = 0;
  const int failures_before = failures;
  frame_planes planes;

  snprintf(path, sizeof path, "%s/%s/stream.hex", suite, test);
  f = fopen(path, "r");
  CHECK(f != NULL, "cannot open %s", path);
  if (!f) return;
  CHECK(read_word(f, &word) && word.w[1] == 0 && word.w[2] == 0 && word.w[3] == 0,
        "%s: line 1 is not a count", path);
  count = word.w[0];
  for (n = 0; n < count && !ended; ++n) {
    uint32_t op;
    if (!read_word(f, &word)) {
      CHECK(0, "%s: word %" PRIu64 " is not 32 hex digits", path, n);
      break;
    }
    op = word.w[3] >> 24;
    CHECK((n == 0) == (op == 0x01), "%s: word %" PRIu64 ": FRAME must come first, and only there", path, n);
    if (op != 0x01 && g == NULL) break;
    switch (op) {
      case 0x01: /* FRAME */
        width = (int)(word.w[0] & 0xffffu);
        height = (int)(word.w[0] >> 16);
        CHECK(zb_golden_create(&g, width, height, (int)(word.w[1] & 0xffu),
                               (int)((word.w[1] >> 8) & 0xffu), word.w[2]) == ZB_OK,
              "%s: create: %s", path, zb_golden_last_error(NULL));
        acc_bits = (int)(word.w[3] & 0xffu);
        rev_bits = (int)((word.w[3] >> 8) & 0xffu);
        CHECK(g && zb_golden_set_wboit(g, acc_bits, rev_bits, (int)((word.w[3] >> 16) & 0xffu)) == ZB_OK,
              "%s: set_wboit: %s", path, zb_golden_last_error(g));
        break;
      case 0x02: /* PASS */
        CHECK(!in_pass && zb_golden_begin_pass(g, word.w[0]) == ZB_OK, "%s: word %" PRIu64 ": begin: %s",
              path, n, zb_golden_last_error(g));
        in_pass = 1;
        pass_fragments = 0;
        break;
      case 0x03: /* FRAG */
        push_checked(g, test, n, (int)(word.w[0] & 0xffffu), (int)(word.w[0] >> 16), word.w[1],
                     word.w[2], (int)(word.w[3] & 0xffu));
        ++pass_fragments;
        ++fragments;
        break;
      case 0x04: { /* END_PASS */
        uint64_t in = 0, passed = 0, dr = 0, dw = 0, cr = 0, cw = 0;
        CHECK(zb_golden_end_pass(g, &in, &passed, &dr, &dw, &cr, &cw) == ZB_OK, "%s: end: %s",
              path, zb_golden_last_error(g));
        CHECK(in == pass_fragments && passed <= in && dw <= passed && cw <= passed && cr <= passed &&
                  dr <= in,
              "%s: word %" PRIu64 ": counters in %" PRIu64 " (sent %" PRIu64 "), passed %" PRIu64
              ", depth %" PRIu64 "/%" PRIu64 ", colour %" PRIu64 "/%" PRIu64,
              path, n, in, pass_fragments, passed, dr, dw, cr, cw);
        in_pass = 0;
        break;
      }
      case 0x05: /* FRAME_OP */
        CHECK(zb_golden_frame_op(g, (int)(word.w[0] & 0xfu), word.w[1], word.w[2]) == ZB_OK,
              "%s: word %" PRIu64 ": frame op: %s", path, n, zb_golden_last_error(g));
        break;
      case 0x06: /* END */
        CHECK(n + 1 == count, "%s: END is word %" PRIu64 " of %" PRIu64, path, n, count);
        ended = 1;
        break;
      default:
        CHECK(0, "%s: word %" PRIu64 ": opcode 0x%02x is unknown", path, n, op);
        ended = 1;
    }
  }
  CHECK(ended && !in_pass, "%s: no END, or a pass left open", path);
  fclose(f);
  if (g == NULL) return;

  if (planes_alloc(&planes, width, height, acc_bits, rev_bits)) {
    planes_by_pixel(g, &planes);
    compare_expect(suite, test, &planes);
  }
  planes_free(&planes);
  zb_golden_destroy(g);
  printf("%s: %s: %" PRIu64 " words, %" PRIu64 " fragments, %dx%d x 5 planes\n", test,
         failures == failures_before ? "equal" : "FAILED", count, fragments, width, height);
}

/* SUITE/TEST through zb_golden_replay_file, every plane read whole: the expect files again. */
static void replay_file(const char* suite, const char* test) {
  char path[4096];
  zb_golden* g = NULL;
  frame_planes planes;
  int width = 0, height = 0, depth_bits = 0, samples = 0, acc_bits = 0, rev_bits = 0, weight = 0;
  const int failures_before = failures;
  snprintf(path, sizeof path, "%s/%s/stream.hex", suite, test);
  if (zb_golden_replay_file(&g, path) != ZB_OK) {
    CHECK(0, "%s: replay_file: %s", test, zb_golden_last_error(NULL));
    return;
  }
  CHECK(zb_golden_frame_info(g, &width, &height, &depth_bits, &samples, &acc_bits, &rev_bits,
                             &weight) == ZB_OK, "%s: frame_info: %s", test, zb_golden_last_error(g));
  if (planes_alloc(&planes, width, height, acc_bits, rev_bits)) {
    int p;
    for (p = 0; p < N_READ_PLANES; ++p)
      CHECK(zb_golden_read_plane(g, p, planes.v[p], (size_t)width * (size_t)height) == ZB_OK,
            "%s: read_plane %d: %s", test, p, zb_golden_last_error(g));
    compare_expect(suite, test, &planes);
  }
  planes_free(&planes);
  zb_golden_destroy(g);
  printf("%s: replay_file: %s: %dx%d, %d-bit depth, %d samples, widths %d %d %d\n", test,
         failures == failures_before ? "equal" : "FAILED", width, height, depth_bits, samples,
         acc_bits, rev_bits, weight);
}

/* A stream made by hand: a 4x2 frame, 16-bit depth, 4 samples, clear 0x11223344, the default
 * accumulation widths; a coverage pass with one full-coverage fragment at (1, 1), depth 100;
 * then depth copied to peel. */
static const char* const kTinyStream[] = {
    "00000000000000000000000000000006", /* the count */
    "01040810112233440000041000020004", /* FRAME */
    "02000000000000000000000000000f73", /* PASS, STATE_COVERAGE */
    "03000004ff0000ff0000006400010001", /* FRAG (1, 1), z 100, rgba ff0000ff, coverage 4 */
    "04000000000000000000000000000000", /* END_PASS */
    "05000000000000000000000000000002", /* FRAME_OP copy depth to peel */
    "06000000000000000000000000000000", /* END */
};
#define TINY_LINES 7

/* The first n lines of kTinyStream, line `at` (0-based) replaced by `with` (at < 0: none), into
 * a new temporary file named in path (32 bytes at least). */
static int write_tiny(char* path, int n, int at, const char* with) {
  FILE* f;
  int fd, i;
  strcpy(path, "/tmp/zb_capi_XXXXXX");
  fd = mkstemp(path);
  CHECK(fd >= 0, "mkstemp %s failed", path);
  if (fd < 0) return 0;
  f = fdopen(fd, "w");
  for (i = 0; f && i < n; ++i) fprintf(f, "%s\n", i == at ? with : kTinyStream[i]);
  if (f) fclose(f);
  return f != NULL;
}

/* replay_file on `path` fails with ZB_EARG, leaves the handle NULL, and its line names the file
 * and holds `want` ("line 4: FRAG: pixel"). */
static void expect_reader_error(int line, const char* path, const char* want) {
  zb_golden* g = (zb_golden*)&failures; /* must be set to NULL */
  const char* e;
  expect_error(line, zb_golden_replay_file(&g, path), ZB_EARG, NULL, "zb_golden_replay_file");
  e = zb_golden_last_error(NULL);
  CHECK(g == NULL, "line %d: a failed replay_file leaves the handle NULL", line);
  CHECK(strstr(e, path) != NULL && strstr(e, want) != NULL,
        "line %d: replay_file's error '%s' should name %s and say '%s'", line, e, path, want);
}

/* The stream reader: a good hand-made stream, then the same stream wrong in one way at a time;
 * bad arguments; the bulk read's and frame_info's errors. */
static void test_reader(void) {
  char path[64];
  zb_golden* g = NULL;
  uint32_t plane[8];
  int i, w = 0, h = 0, d = 0, n = 0, a = 0, r = 0, wt = 0;
  static const uint32_t kDepth[8] = {0xffff, 0xffff, 0xffff, 0xffff, 0xffff, 100, 0xffff, 0xffff};

  if (!write_tiny(path, TINY_LINES, -1, NULL)) return;
  CHECK(zb_golden_replay_file(&g, path) == ZB_OK && g != NULL, "replay_file %s: %s", path,
        zb_golden_last_error(NULL));
  remove(path);
  if (g == NULL) return;
  CHECK(zb_golden_frame_info(g, &w, &h, &d, &n, &a, &r, &wt) == ZB_OK && w == 4 && h == 2 &&
            d == 16 && n == 4 && a == 16 && r == 8 && wt == 4,
        "frame_info: %dx%d, %d, %d, %d %d %d (want 4x2, 16, 4, 16 8 4)", w, h, d, n, a, r, wt);
  CHECK(zb_golden_read_plane(g, ZB_PLANE_DEPTH, plane, 8) == ZB_OK, "read_plane: %s",
        zb_golden_last_error(g));
  for (i = 0; i < 8; ++i)
    CHECK(plane[i] == kDepth[i], "depth pixel %d: %x, want %x (row-major)", i, plane[i], kDepth[i]);
  CHECK(zb_golden_read_plane(g, ZB_PLANE_PEEL, plane, 8) == ZB_OK && plane[5] == 100 &&
            plane[0] == 0xffff, "the copy to peel: peel (1, 1) %u, (0, 0) %x", plane[5], plane[0]);
  CHECK(read_plane(g, ZB_PLANE_COVERAGE, 1, 1) == 4 && read_plane(g, ZB_PLANE_COLOR, 0, 0) == 0x11223344u,
        "coverage (1, 1) and the clear colour");
  EXPECT_ERROR(zb_golden_read_plane(g, ZB_PLANE_DEPTH, plane, 7), ZB_EARG, g, "zb_golden_read_plane");
  EXPECT_ERROR(zb_golden_read_plane(g, ZB_PLANE_DEPTH, NULL, 8), ZB_EARG, g, "zb_golden_read_plane");
  EXPECT_ERROR(zb_golden_read_plane(g, 9, plane, 8), ZB_EARG, g, "zb_golden_read_plane");
  EXPECT_ERROR(zb_golden_read_plane(NULL, 0, plane, 8), ZB_EHANDLE, NULL, "zb_golden_read_plane");
  EXPECT_ERROR(zb_golden_frame_info(NULL, &w, NULL, NULL, NULL, NULL, NULL, NULL), ZB_EHANDLE, NULL,
               "zb_golden_frame_info");
  /* The replayed frame is between passes: it takes more. */
  CHECK(zb_golden_begin_pass(g, STATE_COVERAGE) == ZB_OK &&
            zb_golden_push(g, 0, 0, 5, 0xff00ff00u, 4, NULL, NULL, NULL, NULL) == ZB_OK &&
            zb_golden_end_pass(g, NULL, NULL, NULL, NULL, NULL, NULL) == ZB_OK &&
            read_plane(g, ZB_PLANE_DEPTH, 0, 0) == 5,
        "a pass after the replay: %s", zb_golden_last_error(g));
  zb_golden_destroy(g);

  /* Each wrong in one way: the line named, what is wrong said. */
  {
    static const struct {
      int lines, at;
      const char* with;
      const char* want;
    } kBad[] = {
        {TINY_LINES, 3, "03000004ff0000ff0000006400010004", "line 4: FRAG: pixel (4, 1) is outside"},
        {TINY_LINES, 3, "03000005ff0000ff0000006400010001", "line 4: FRAG: coverage 5 exceeds"},
        {TINY_LINES, 3, "03000004ff0000ff0001000000010001", "line 4: FRAG: depth 0x10000 exceeds"},
        {TINY_LINES, 2, "03000004ff0000ff0000006400010001", "line 3: FRAG outside a pass"},
        {TINY_LINES, 2, "020000000000000000000000000000e0", "line 3: PASS: state 0xe0"},
        {TINY_LINES, 1, "01040810112233440000111000020004", "line 2: FRAME: coverage_samples 17"},
        {TINY_LINES, 1, "02000000000000000000000000000f73", "line 2: the first word is PASS"},
        {TINY_LINES, 4, "0400000000000000000000000000000g", "line 5: column 32: character 0x67"},
        {TINY_LINES, 4, "0400000000000000000000000000001", "line 5: 31 characters"},
        {TINY_LINES, 4, "04000000000000000000000000000001", "line 5: END_PASS has bits set"},
        {TINY_LINES, 4, "05000000000000000000000000000002", "line 5: FRAME_OP inside the pass that line 3"},
        {TINY_LINES, 5, "05000000000000000000000000000006", "line 6: FRAME_OP: kind 6"},
        {TINY_LINES, 2, "02000000000000000000000000010f73", "line 3: PASS has bits set outside"},
        {TINY_LINES, 5, "07000000000000000000000000000000", "line 6: opcode 0x07"},
        {TINY_LINES, 0, "00000000000000000000000000000005", "line 6: the last word is FRAME_OP, not END"},
        {TINY_LINES, 0, "00000000000000000000000000000001", "line 1: the count line announces 1 word:"},
        {TINY_LINES, 0, "00000000000000010000000000000006", "line 1: the count line is not a count"},
        {5, -1, NULL, "line 6: the file ends here, but its count line announces 6 words"},
        {0, -1, NULL, "line 1: the file is empty"},
    };
    for (i = 0; i < (int)(sizeof kBad / sizeof kBad[0]); ++i) {
      if (!write_tiny(path, kBad[i].lines, kBad[i].at, kBad[i].with)) return;
      expect_reader_error(__LINE__, path, kBad[i].want);
      remove(path);
    }
  }
  /* A line after END. */
  if (write_tiny(path, TINY_LINES, -1, NULL)) {
    FILE* f = fopen(path, "a");
    if (f) {
      fputs(kTinyStream[6], f);
      fputc('\n', f);
      fclose(f);
    }
    expect_reader_error(__LINE__, path, "line 8: a line after END");
    remove(path);
  }
  expect_reader_error(__LINE__, "/nonexistent/stream.hex", "cannot open");
  expect_reader_error(__LINE__, "/tmp", "is a directory");
  EXPECT_ERROR(zb_golden_replay_file(NULL, "/tmp"), ZB_EARG, NULL, "zb_golden_replay_file");
  EXPECT_ERROR(zb_golden_replay_file(&g, NULL), ZB_EARG, NULL, "zb_golden_replay_file");
}

/* A suite's stream cut after `keep` lines: the reader names the line where it ends. */
static void test_truncated(const char* suite, const char* test, int keep) {
  char src[4096], path[64], line[80], want[64];
  FILE *in, *out;
  int fd, i;
  snprintf(src, sizeof src, "%s/%s/stream.hex", suite, test);
  in = fopen(src, "r");
  CHECK(in != NULL, "cannot open %s", src);
  if (!in) return;
  strcpy(path, "/tmp/zb_capi_XXXXXX");
  fd = mkstemp(path);
  out = fd >= 0 ? fdopen(fd, "w") : NULL;
  CHECK(out != NULL, "cannot write %s", path);
  for (i = 0; out && i < keep && fgets(line, sizeof line, in); ++i) fputs(line, out);
  fclose(in);
  if (!out) return;
  fclose(out);
  snprintf(want, sizeof want, "line %d: the file ends here", keep + 1);
  expect_reader_error(__LINE__, path, want);
  expect_reader_error(__LINE__, path, "truncated");
  remove(path);
}

static int is_test_dir(const char* suite, const char* name) {
  char path[4096];
  FILE* f;
  if (name[0] == '.') return 0;
  snprintf(path, sizeof path, "%s/%s/stream.hex", suite, name);
  f = fopen(path, "r");
  if (f) fclose(f);
  return f != NULL;
}

int main(int argc, char** argv) {
  int i, tests = 0;
  if (argc < 2) {
    fprintf(stderr, "usage: test_capi SUITE [TEST...]\n");
    return 2;
  }
  test_errors();
  test_accumulate();
  test_arithmetic();
  test_layers();
  test_reader();
  if (argc > 2) {
    for (i = 2; i < argc; ++i, ++tests) {
      replay(argv[1], argv[i]);
      replay_file(argv[1], argv[i]);
    }
    test_truncated(argv[1], argv[2], 100);
  } else {
    DIR* d = opendir(argv[1]);
    struct dirent* e;
    CHECK(d != NULL, "cannot open the suite %s", argv[1]);
    while (d && (e = readdir(d)) != NULL)
      if (is_test_dir(argv[1], e->d_name)) {
        replay(argv[1], e->d_name);
        replay_file(argv[1], e->d_name);
        if (tests++ == 0) test_truncated(argv[1], e->d_name, 100);
      }
    if (d) closedir(d);
  }
  CHECK(tests > 0, "no test replayed: the suite %s holds none", argv[1]);
  printf("test_capi: %d tests replayed, %d failures\n", tests, failures);
  return failures ? 1 : 0;
}
