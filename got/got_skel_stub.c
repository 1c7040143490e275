/*
** got_skel_stub.c: TEMPORARY stand-in for got_skel_build until branch skel lands (deleted
** by that merge): the skeleton of all edges, which is sound for every rule.
*/
#include "got_skel.h"

int got_skel_build(const geom_point *p, size_t n, const rule *r, int threads, got_skel *out,
                   char *err, size_t errlen) {
  (void)r, (void)threads;
  return got_skel_all(p, n, out, err, errlen);
}
