/*
** testutil.h: helpers shared by the tests: a seeded generator, random
** convex quadrilaterals and their four triangles, a near-equality check,
** running the fliplab program and capturing output.
*/
#ifndef FLIPLAB_TESTUTIL_H
#define FLIPLAB_TESTUTIL_H

#include <stddef.h>
#include <stdint.h>
#include "fliplab_config.h"
#include "geom.h"

/* splitmix64: a small seeded generator for test data. */
typedef struct testutil_rng { uint64_t s; } testutil_rng;
uint64_t testutil_next(testutil_rng *g);
double testutil_uniform(testutil_rng *g);               /* [0, 1) */

/* n sites (n <= 400) of the paradigm tests' family f: 0 uniform, 1 draws
** from a 6 x 6 grid (duplicates), 2 a grid 7 wide, 3 draws from 24 points
** of a circle, 4 collinear runs on three lines with a few off them, 5
** integer points of two concentric circles with repeats.  Returns n. */
size_t testutil_family(int f, size_t n, testutil_rng *g, geom_point *p);

/* Fails the running cmocka test, naming WHAT, unless the triangle arrays
** a (na triangles) and b (nb) are equal. */
void testutil_same_tri(const uint32_t *a, size_t na, const uint32_t *b, size_t nb,
                       const char *what);

/* Four points uniform in the unit disc whose hull is a quadrilateral,
** returned anticlockwise. */
void testutil_convex_quad(testutil_rng *g, geom_point q[4]);

/* The four triangles of the quadrilateral q = ABCD, in the order
** rule_eval_tris takes them: t[0] = ABC, t[1] = ACD (the diagonal AC),
** t[2] = ABD, t[3] = BCD (the diagonal BD). */
void testutil_quad_tris(const geom_point q[4], geom_tri t[4]);

/* Fails the running cmocka test unless |got - want| <= abs + rel * |want|
** (so a NaN always fails), printing WHAT, the values and the tolerance.
** TESTUTIL_NEAR names the expression and the caller's line. */
void testutil_near(double got, double want, double rel, double abs,
                   const char *what, const char *file, int line);
#define TESTUTIL_NEAR(got, want, rel, abs) \
  testutil_near((got), (want), (rel), (abs), #got, __FILE__, __LINE__)

/* Fails the running cmocka test unless p[0..n) is strictly convex and
** anticlockwise (geom_polygon_check, exact; p itself is not changed). */
void testutil_check_convex(const geom_point *p, size_t n);

/* Whether s is exactly one line: its only '\n' is its last character
** (the "one clear line on stderr" of every refusal). */
int testutil_one_line(const char *s);

/* Run `fliplab ARGS` through /bin/sh; capture stdout and stderr (each up to
** cap bytes, NUL-terminated; either may be NULL).  Returns the exit status. */
int testutil_run(const char *args, char *out, size_t outcap, char *err, size_t errcap);
/* The same with standard input read from the file `in`. */
int testutil_run_in(const char *in, const char *args, char *out, size_t outcap, char *err,
                    size_t errcap);

/* testutil_run with standard output sent to the file stdout_path (e.g.
** /dev/full) instead of being captured. */
int testutil_run_to(const char *args, const char *stdout_path, char *err, size_t errcap);

/* testutil_run with the arguments made by printf from FMT (at most 4095
** characters: the tests' commands are far shorter). */
int testutil_runf(char *out, size_t outcap, char *err, size_t errcap, const char *fmt, ...)
  FLIPLAB_PRINTF(5, 6);

/* The whole file as a NUL-terminated malloc'ed string (NULL if it cannot
** be read); write text to a file, failing the test if it cannot. */
char *testutil_read_file(const char *path);
void testutil_write_file(const char *path, const char *text);

/* The six orders of three vertices, for checks that a triangle's value
** does not depend on the order it is given in. */
extern const int testutil_perm3[6][3];

/* Non-overlapping occurrences of needle in hay. */
size_t testutil_count(const char *hay, const char *needle);

/* A fresh path in the build tree for a test's files. */
void testutil_tmppath(char *buf, size_t len, const char *name);

/* How many times to repeat a sampled check: n in the optimised builds; a
** quarter of n (at least 1) in the sanitizer build (FLIPLAB_TEST_SANITIZED),
** which is there to find memory and undefined-behaviour errors on every
** path, not to repeat the statistics the optimised builds check in full. */
int testutil_reps(int n);

/* Register (once) three user measures with extreme values, for the engines'
** exact fallbacks: "xwide" (>= 0) and "-xwide" (<= 0), magnitudes from
** 2^-900 to 2^900 (products and squares under- and overflow), and "xinf"
** (>= 0): +inf, 0, the least subnormal or R.  Their ids into ids; 0, or
** -1 if the registry is full. */
int testutil_extreme_measures(int ids[3]);

#endif
