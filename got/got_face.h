/* got_face.h: the optimal triangulations of one face of a point set's skeleton, exactly
** (private to got/).  A face: a region of the plane bounded by certain edges, given by its
** closed boundary walks (face on the left; an edge with the face on both sides is walked
** twice), the points strictly inside it, and the candidate edges allowed inside it. */
#ifndef FLIPLAB_GOT_FACE_H
#define FLIPLAB_GOT_FACE_H

#include <stddef.h>
#include <stdint.h>
#include "fliplab_config.h"
#include "geom.h"
#include "rule.h"

typedef struct got_face_in {
  const geom_point *p;      /* all points of the set (indices below refer to it) */
  size_t nwalks;
  const size_t *walk_len;   /* vertices of each closed walk */
  const uint32_t *walk;     /* the walks' vertices, concatenated (first walk: the outer one) */
  const uint32_t *inner;    /* points strictly inside the face touching no boundary edge */
  size_t ninner;
  const uint32_t *edge;     /* candidate edges allowed inside the face, 2 per edge */
  size_t nedges;
} got_face_in;
typedef struct got_face_out {
  uint32_t *tri;            /* 3 per triangle, anticlockwise: an optimal triangulation */
  size_t ntri;
  double key;               /* its total in key space (sum of rule_key of each badness) */
  int has_runner_up;        /* 0 when the face has one triangulation only */
  double key2;              /* the least total of any other triangulation of the face */
  double err, err2;         /* certified bounds |exact - key| <= err, exact(other) >= key2 - err2 */
  int unique;               /* 1 when key2 - key > err + err2 (proven unique) */
  size_t states;            /* search states visited (statistics) */
} got_face_out;
/* Solve the face for the sum rule r: 0, or -1 with a one-line message (a face too large for
** the exact search: say its size and the limit; out of memory). */
FLIPLAB_INTERNAL
int got_face_solve(const got_face_in *in, const rule *r, got_face_out *out, char *err,
                   size_t errlen);
FLIPLAB_INTERNAL
void got_face_out_free(got_face_out *o);
/* got_face_solve with another limit on the regions searched (got_face_solve: 2^20; tests
** use small ones to see the refusal). */
FLIPLAB_INTERNAL
int got_face_solve_limit(const got_face_in *in, const rule *r, size_t max_states,
                         got_face_out *out, char *err, size_t errlen);

#endif
