/*
** got_skel.c: the skeleton of a point set's GOT for a sum rule (got/got_skel.h): candidate
** edges, the LMT-skeleton loop, and the certain edges (docs/got.md, "Point sets: the
** skeleton").  Work in progress: got_skel_free only.
*/
#include <stdlib.h>
#include "got_skel.h"

void got_skel_free(got_skel *s) {
  if (!s) return;
  free(s->edge);
  free(s->state);
  s->edge = NULL;
  s->state = NULL;
  s->nedges = 0;
}
