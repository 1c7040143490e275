/*
** sites.c: a rule's systematicity beyond convex pentagons: the census of
** random site sets (classify/siteflip.h) and the first set with two or more
** LOTs, a witness `fliplab flipgraph` reads back bit for bit.
*/
#include <string.h>
#include "study.h"

/* The census's cost (one flip graph per set), then a scan up to the witness. */
int study_sites(const rule *r, int sampler, int n, uint64_t seed, uint64_t samples,
                double tie_eps, int threads, study_sitecheck *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  out->sampler = sampler;
  out->n = n;
  if (siteflip_census(r, 1, sampler, n, seed, 0, samples, tie_eps, threads, 0, &out->counts,
                      NULL, NULL, NULL, err, errlen) != 0)
    return -1;
  out->decided = out->counts.samples - out->counts.tie;
  out->systematic = out->counts.multi_sink == 0;
  int64_t w = out->systematic ? -1 : siteflip_find_multi(r, sampler, n, seed, 0, samples,
                                                          tie_eps, out->sites);
  out->has_witness = w >= 0;
  out->witness = w >= 0 ? (uint64_t)w : 0;
  return 0;
}
