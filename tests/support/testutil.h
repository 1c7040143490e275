/*
** testutil.h: helpers shared by the tests: a seeded generator, random
** convex quadrilaterals, running the fliplab program and capturing output.
*/
#ifndef FLIPLAB_TESTUTIL_H
#define FLIPLAB_TESTUTIL_H

#include <stddef.h>
#include <stdint.h>
#include "geom/geom.h"

/* splitmix64: a small seeded generator for test data. */
typedef struct testutil_rng { uint64_t s; } testutil_rng;
uint64_t testutil_next(testutil_rng *g);
double testutil_uniform(testutil_rng *g);               /* [0, 1) */

/* Four points uniform in the unit disc whose hull is a quadrilateral,
** returned anticlockwise. */
void testutil_convex_quad(testutil_rng *g, geom_point q[4]);

/* Run `fliplab ARGS` through /bin/sh; capture stdout and stderr (each up to
** cap bytes, NUL-terminated; either may be NULL).  Returns the exit status. */
int testutil_run(const char *args, char *out, size_t outcap, char *err, size_t errcap);

/* A fresh path in the build tree for a test's files. */
void testutil_tmppath(char *buf, size_t len, const char *name);

#endif
