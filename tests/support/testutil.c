/*
** testutil.c: helpers shared by the tests.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <string.h>
#include <unistd.h>
#include "testutil.h"
#include "measure.h"
#include "sampler.h"
#include "splitmix.h"

const int testutil_perm3[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

uint64_t testutil_next(testutil_rng *g) {
  return geom_splitmix64(&g->s);
}

double testutil_uniform(testutil_rng *g) {
  return geom_unit53(testutil_next(g));
}

/* One sampler for every random quadrilateral: samplers/'s, on a stream
** chosen by this generator. */
void testutil_convex_quad(testutil_rng *g, geom_point q[4]) {
  sampler_quad(testutil_next(g), 0, q);
}

void testutil_quad_tris(const geom_point q[4], geom_tri t[4]) {
  geom_tri_make(&t[0], q[0], q[1], q[2]);
  geom_tri_make(&t[1], q[0], q[2], q[3]);
  geom_tri_make(&t[2], q[0], q[1], q[3]);
  geom_tri_make(&t[3], q[1], q[2], q[3]);
}

void testutil_near(double got, double want, double rel, double abs,
                   const char *what, const char *file, int line) {
  double tol = abs + rel * fabs(want);
  if (!(fabs(got - want) <= tol)) {
    print_error("%s: got %.17g, want %.17g (tol %.3g)\n", what, got, want, tol);
    _fail(file, line);
  }
}

int testutil_one_line(const char *s) {
  const char *nl = strchr(s, '\n');
  return nl != NULL && nl[1] == '\0';
}

static void testutil_slurp(const char *path, char *buf, size_t cap) {
  if (buf == NULL || cap == 0) return;
  buf[0] = '\0';
  FILE *f = fopen(path, "rb");
  if (f == NULL) return;
  size_t n = fread(buf, 1, cap - 1, f);
  buf[n] = '\0';
  fclose(f);
}

/* The folder is made here, so that a test that writes its inputs before
** running the program (which makes it too) works alone in a new build. */
void testutil_tmppath(char *buf, size_t len, const char *name) {
  mkdir(FLIPLAB_BUILD_DIR "/testtmp", 0777);   /* EEXIST is fine */
  snprintf(buf, len, "%s/testtmp/%ld-%s", FLIPLAB_BUILD_DIR, (long)getpid(), name);
}

int testutil_run(const char *args, char *out, size_t outcap, char *err, size_t errcap) {
  return testutil_run_in("/dev/null", args, out, outcap, err, errcap);
}

int testutil_run_in(const char *in, const char *args, char *out, size_t outcap, char *err,
                    size_t errcap) {
  char o[512], e[512], cmd[8192];
  testutil_tmppath(o, sizeof o, "stdout");
  testutil_tmppath(e, sizeof e, "stderr");
  snprintf(cmd, sizeof cmd, "%s %s <%s >%s 2>%s", FLIPLAB_BIN, args, in, o, e);
  int st = system(cmd);
  testutil_slurp(o, out, outcap);
  testutil_slurp(e, err, errcap);
  unlink(o);
  unlink(e);
  if (st == -1) return -1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

int testutil_run_to(const char *args, const char *stdout_path, char *err, size_t errcap) {
  char e[512], cmd[8192];
  testutil_tmppath(e, sizeof e, "stderr");
  snprintf(cmd, sizeof cmd, "%s %s </dev/null >%s 2>%s", FLIPLAB_BIN, args, stdout_path, e);
  int st = system(cmd);
  testutil_slurp(e, err, errcap);
  unlink(e);
  if (st == -1) return -1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

int testutil_runf(char *out, size_t outcap, char *err, size_t errcap, const char *fmt, ...) {
  char args[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(args, sizeof args, fmt, ap);
  va_end(ap);
  return testutil_run(args, out, outcap, err, errcap);
}

char *testutil_read_file(const char *path) {
  FILE *f = fopen(path, "rb");
  if (f == NULL) return NULL;
  size_t cap = 1 << 16, n = 0, got;
  char *s = malloc(cap);
  while (s != NULL && (got = fread(s + n, 1, cap - n - 1, f)) > 0) {
    n += got;
    if (n + 1 == cap) s = realloc(s, cap *= 2);
  }
  fclose(f);
  if (s != NULL) s[n] = '\0';
  return s;
}

void testutil_write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  fputs(text, f);
  assert_int_equal(fclose(f), 0);
}

size_t testutil_count(const char *hay, const char *needle) {
  size_t n = 0;
  for (const char *p = hay; (p = strstr(p, needle)) != NULL; p += strlen(needle)) n++;
  return n;
}

/* ---- extreme measures ------------------------------------------------------ */

/* 0..7 from low-order bits of a vertex coordinate: a fixed, well-mixed
** choice per triangle. */
static int testutil_bucket(const geom_tri *t) {
  uint64_t u;
  memcpy(&u, &t->v[1].y, sizeof u);
  return (int)((u >> 11 ^ u >> 29) & 7);
}

static double testutil_wide(const geom_tri *t, void *ctx) {
  (void)ctx;
  return ldexp(t->P, (testutil_bucket(t) - 4) * 225);   /* 2^-900 .. 2^675 times P */
}

static double testutil_negwide(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -ldexp(t->area, (testutil_bucket(t) - 3) * 225);
}

static double testutil_infzero(const geom_tri *t, void *ctx) {
  (void)ctx;
  int b = testutil_bucket(t);
  return b == 0 ? INFINITY : b == 1 ? 0.0 : b == 2 ? 0x1p-1074 : t->R;
}

int testutil_reps(int n) {
#ifdef FLIPLAB_TEST_SANITIZED
  return n >= 4 ? n / 4 : n > 0 ? 1 : n;
#else
  return n;
#endif
}

int testutil_extreme_measures(int ids[3]) {
  static const measure m[3] = {
    {"xwide", "xwide", "test: P scaled by 2^-900 .. 2^675", MEASURE_NONNEG, testutil_wide, NULL},
    {"-xwide", "-xwide", "test: -A scaled by 2^-675 .. 2^900", MEASURE_NONPOS, testutil_negwide,
     NULL},
    {"xinf", "xinf", "test: +inf, 0, the least subnormal or R", MEASURE_NONNEG, testutil_infzero,
     NULL}};
  for (int k = 0; k < 3; k++) {
    ids[k] = measure_find(m[k].name);
    if (ids[k] < 0) ids[k] = measure_register(&m[k]);
    if (ids[k] < 0) return -1;
  }
  return 0;
}

void testutil_check_convex(const geom_point *p, size_t n) {
  geom_point *q = malloc(n * sizeof *q);
  assert_non_null(q);
  memcpy(q, p, n * sizeof *q);
  size_t bad = 0;
  int rev = 1;
  assert_int_equal(geom_polygon_check(q, n, &bad, &rev), GEOM_OK);
  assert_false(rev);
  free(q);
}

size_t testutil_family(int f, size_t n, testutil_rng *g, geom_point *p) {
  for (size_t i = 0; i < n; i++) {
    uint64_t a = testutil_next(g) % 6, b = testutil_next(g) % 6;
    double t = 6.283185307179586 * (double)(testutil_next(g) % 24) / 24;
    switch (f) {
      case 0: p[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)}; break;
      case 1: p[i] = (geom_point){(double)a, (double)b}; break;   /* grid, duplicates */
      case 2: p[i] = (geom_point){(double)(i % 7), (double)(i / 7)}; break;   /* grid */
      case 3: p[i] = (geom_point){5 * cos(t), 5 * sin(t)}; break;   /* 24 on a circle */
      case 4:   /* collinear runs on three lines, a few off them */
        p[i] = i % 4 == 3 ? (geom_point){testutil_uniform(g) * 8, testutil_uniform(g) * 8}
             : (geom_point){(double)(i % 4 == 0 ? a : i % 4 == 1 ? 0 : a),
                            (double)(i % 4 == 0 ? 0 : i % 4 == 1 ? b : a)};
        break;
      default:  /* integer points of two concentric circles, with repeats */
        {
          static const int c[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                     {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
          int k = (int)(testutil_next(g) % 12), s = (int)(testutil_next(g) % 2) + 1;
          p[i] = (geom_point){s * c[k][0], s * c[k][1]};
        }
    }
  }
  return n;
}

void testutil_same_tri(const uint32_t *a, size_t na, const uint32_t *b, size_t nb,
                       const char *what) {
  if (na != nb || (na > 0 && memcmp(a, b, 3 * na * sizeof *a) != 0))
    fail_msg("%s: triangles differ (%zu against %zu)", what, na, nb);
}
