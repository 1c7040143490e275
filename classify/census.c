/*
** census.c: the scaffolding of classify/'s two census engines
** (census_internal.h): the plan of the rules, the deterministic chunked
** parallel loop, and the sample range of a shard (census.h).
*/
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "census_internal.h"

/* One slot per measure some triangle rule uses, in measure order. */
static void census_plan_slots(census_plan *pl, const unsigned char *used) {
  int slot_of[MEASURE_MAX];
  for (int m = 0; m < MEASURE_MAX; m++) {
    if (!used[m]) continue;
    int s = pl->nslots++;
    slot_of[m] = s;
    pl->slot_measure[s] = m;
    pl->slot_sign[s] = measure_get(m)->sign == MEASURE_NONPOS ? -1.0 : 1.0;
  }
  for (int i = 0; i < pl->nrules; i++)
    if (pl->item[i].kind == CENSUS_TRIANGLE)
      pl->item[i].slot = slot_of[rule_measure(&pl->rules[i])];
  pl->eval_all_ok = 1;
  for (int m = MEASURE_BUILTIN_COUNT; m < measure_count(); m++)
    if (!used[m]) pl->eval_all_ok = 0;
}

int census_plan_make(census_plan *pl, const rule *rules, int nrules) {
  memset(pl, 0, sizeof *pl);
  for (int s = 0; s < CENSUS_SLOTS; s++) pl->slot_sign[s] = 1.0;
  if (nrules < 0 || (nrules > 0 && rules == NULL)) return -1;
  pl->rules = rules;
  pl->nrules = nrules;
  if ((pl->item = calloc((size_t)nrules + 1, sizeof *pl->item)) == NULL) return -2;
  unsigned char used[MEASURE_MAX] = {0};
  for (int i = 0; i < nrules; i++) {
    const rule *r = &rules[i];
    census_item *it = &pl->item[i];
    if (!rule_is_triangle(r)) {
      if (rule_quad_of(r) == NULL) return -1;
      it->kind = rule_is_delaunay(r) ? CENSUS_DT : CENSUS_QUAD;
      *(it->kind == CENSUS_DT ? &pl->ndt : &pl->nquad) += 1;
      continue;
    }
    int m = rule_measure(r);
    joint_id j = rule_joint(r);
    if (m < 0 || m >= measure_count() || joint_get(j) == NULL) return -1;
    it->kind = CENSUS_TRIANGLE;
    it->joint = j;
    used[m] = 1;
    pl->joint_used[j] = 1;
  }
  census_plan_slots(pl, used);
  return 0;
}

void census_plan_free(census_plan *pl) {
  free(pl->item);
  pl->item = NULL;
}

int census_threads(int threads, uint64_t count, uint64_t chunk) {
  threads = geom_threads_clamp(threads, omp_get_max_threads());
  uint64_t nchunks = (count + chunk - 1) / chunk;
  if ((uint64_t)threads > nchunks) threads = nchunks > 0 ? (int)nchunks : 1;
  return threads;
}

int census_loop_run(const census_loop *l) {
  const uint64_t nchunks = (l->count + l->chunk - 1) / l->chunk;
  uint64_t done = 0;
  int failed = 0;
#pragma omp parallel num_threads(l->threads)
  {
    int me = omp_get_thread_num();
#pragma omp for schedule(dynamic, 1)
    for (uint64_t k = 0; k < nchunks; k++) {
      uint64_t lo = l->first + k * l->chunk;
      uint64_t hi = k + 1 == nchunks ? l->first + l->count : lo + l->chunk;
      int bad;
#pragma omp atomic read
      bad = failed;
      if (bad) continue;
      if (l->range(l->ctx, me, lo, hi) != 0) {
#pragma omp atomic write
        failed = 1;
      }
      uint64_t now;
#pragma omp atomic capture
      now = done += hi - lo;
      if (l->progress != NULL && me == 0) l->progress(now, l->count, l->progress_ctx);
    }
  }
  if (l->progress != NULL && !failed) l->progress(l->count, l->count, l->progress_ctx);
  return failed ? -1 : 0;
}

/* floor((k-1) total / n) without overflow for n <= 2^32: with total = q n +
** r, it is (k-1) q + floor((k-1) r / n), and (k-1) r < n^2 <= 2^64. */
static uint64_t census_shard_start(uint64_t total, uint64_t k, uint64_t n) {
  uint64_t q = total / n, r = total % n;
  return (k - 1) * q + (k - 1) * r / n;
}

int census_shard_range(uint64_t total, uint64_t k, uint64_t n, uint64_t *first,
                       uint64_t *count) {
  if (n == 0 || n > (1ull << 32) || k == 0 || k > n) return -1;
  *first = census_shard_start(total, k, n);
  *count = (k == n ? total : census_shard_start(total, k + 1, n)) - *first;
  return 0;
}
