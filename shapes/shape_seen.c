/*
** shape_seen.c: exact answers kept per thread and asked again.  The shape
** predicates and the empty-shape decision are translation-invariant: they
** read the sites as differences, exactly, so an answer is a function of
** the shape, a few small integers (program, edges, corner) and those
** differences.  On a grid the differences are small integers and the same
** few configurations come back at many places; a direct-mapped table per
** thread, keyed by exactly that, answers them again (shape_internal.h).
*/
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>
#include "geom_exact_internal.h"
#include "shape_internal.h"

/* ---- why a kept answer is the answer --------------------------------------
**
** A key holds the shape's serial number (no two shapes of the process share
** one, unlike addresses, which are reused after a free), what was asked
** (a program or the decision) with its integers, and the differences of the
** sites to an origin, kept only when every one is exact (geom_two_diff's
** error 0: the doubles are then the differences themselves).  Two equal
** keys therefore ask the same exact quantity of the same shape, whose
** answer does not depend on where the sites are.  The table only ever
** holds answers computed exactly, so a hit returns what the computation
** would.  It is per thread (_Thread_local): no locks, and the same answers
** whatever the thread count.  The tests' reference modes (exact only, GMP
** only) neither read nor fill it, so comparing with them checks it too.
** Cost: a hash of the key's 13 words and one comparison; a slot is
** overwritten by the next key that falls on it. */

#define SHAPE_SEEN_SLOTS 1024

typedef struct shape_seen_slot {
  shape_seen_key k;
  int v, used;
} shape_seen_slot;

static _Thread_local shape_seen_slot shape_seen_table[SHAPE_SEEN_SLOTS];
static atomic_ulong shape_seen_count[SHAPE_SEEN_WHATS];

unsigned long shape_seen_hits(int what) {
  return atomic_load_explicit(&shape_seen_count[what], memory_order_relaxed);
}

int shape_seen_on(void) {
  return !shape_exact_only() && !geom_exact_gmp_forced();
}

void shape_seen_start(shape_seen_key *k, const shape *K, int what, const int *n, int cnt) {
  memset(k, 0, sizeof *k);   /* keys are compared as bytes */
  k->serial = K->impl->serial;
  k->what = what;
  for (int i = 0; i < cnt; i++) k->n[i] = n[i];
}

int shape_seen_diffs(shape_seen_key *k, const geom_point *p, int rows, geom_point o) {
  int exact = 1;
  for (int r = 0; r < rows; r++) {
    double ex, ey;
    geom_two_diff(p[r].x, o.x, &k->d[2 * r], &ex);
    geom_two_diff(p[r].y, o.y, &k->d[2 * r + 1], &ey);
    exact &= (ex == 0) & (ey == 0);
  }
  return exact;
}

/* The slot of key k: its words mixed in turn, each multiplication
** followed by a shift down (a double's small integers differ in their top
** bits, which a multiplication alone never carries down to the slot's). */
static shape_seen_slot *shape_seen_slot_of(const shape_seen_key *k) {
  uint64_t w[sizeof *k / sizeof(uint64_t)], h = 0;
  memcpy(w, k, sizeof w);
  for (size_t i = 0; i < sizeof w / sizeof w[0]; i++) {
    h = (h ^ w[i]) * 0x9e3779b97f4a7c15u;
    h ^= h >> 29;
  }
  return &shape_seen_table[h % SHAPE_SEEN_SLOTS];
}

int shape_seen_find(const shape_seen_key *k, int *v) {
  const shape_seen_slot *s = shape_seen_slot_of(k);
  if (!s->used || memcmp(&s->k, k, sizeof *k) != 0) return 0;
  atomic_fetch_add_explicit(&shape_seen_count[k->what], 1, memory_order_relaxed);
  *v = s->v;
  return 1;
}

void shape_seen_keep(const shape_seen_key *k, int v) {
  shape_seen_slot *s = shape_seen_slot_of(k);
  *s = (shape_seen_slot){.k = *k, .v = v, .used = 1};
}
