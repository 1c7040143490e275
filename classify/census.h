/*
** census.h: what the two census engines of classify/ (the pentagons of
** table34, flipgraph.h; the site sets of census, siteflip.h) offer alike:
** the progress callback of their tallies and the sample range of a shard.
*/
#ifndef FLIPLAB_CENSUS_H
#define FLIPLAB_CENSUS_H

#include <stdint.h>

/* Called now and then from one thread with the samples done out of total,
** and once at the end with done == total. */
typedef void (*census_progress_fn)(uint64_t done, uint64_t total, void *ctx);

/* Shard k of n (1 <= k <= n <= 2^32) of the samples [0, total):
** *first = floor((k-1) total / n), *count = floor(k total / n) - *first, so
** the shards 1/n .. n/n tile [0, total) in order.  0, or -1 for a bad k/n
** (then nothing is set). */
int census_shard_range(uint64_t total, uint64_t k, uint64_t n, uint64_t *first,
                       uint64_t *count);

#endif
