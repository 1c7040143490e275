/*
** benchutil.h: what every benchmark of bench/ needs besides the code it
** times: wall and CPU clocks, the median of repeated runs, the load
** average printed beside the figures, and seeded polygons to time.  One
** home, so that every table of docs/performance.md is measured the same way.
*/
#ifndef FLIPLAB_BENCHUTIL_H
#define FLIPLAB_BENCHUTIL_H

#include <stddef.h>
#include "sampler.h"

/* Seconds on the monotonic clock (wall time). */
double bench_wall(void);
/* CPU seconds of the whole process, all threads: on a loaded machine the
** steadier figure (CPU / cores is the wall time on idle cores). */
double bench_cpu(void);

/* Wall and CPU seconds of one run. */
typedef struct bench_time { double wall, cpu; } bench_time;

/* The median of v[0..n-1] (sorts v). */
double bench_median(double *v, int n);
/* The run of median wall time among t[0..n-1] (sorts t by wall time). */
bench_time bench_median_time(bench_time *t, int n);

/* The one-minute load average (Linux /proc/loadavg), or NAN. */
double bench_load(void);

/* Run the program `name ARGS` that lies beside argv0 (a C++ comparison)
** and read its "cgal_seconds W" and "cgal_cpu_seconds C" lines into *wall
** and *cpu: NAN when it is not built or prints neither. */
void bench_sibling(const char *argv0, const char *name, const char *args, double *wall,
                   double *cpu);

/* One LOT of rule r on the n points p with default options (lot_build):
** its wall and CPU seconds, and its statistics into *stats (may be NULL);
** exits with a message naming prog if it fails. */
struct rule;
struct lot_stats;
bench_time bench_lot_time(const char *prog, const struct rule *r, const geom_point *p, size_t n,
                          struct lot_stats *stats);

/* A polygon sampler of samplers/sampler.h (sampler_vector, sampler_star...). */
typedef int (*bench_sampler)(sampler_rng *g, size_t n, geom_point *out);
/* n vertices from fn with seed 1 (malloc'd); exits with a message naming
** prog if the sampler or the allocation fails. */
geom_point *bench_polygon(const char *prog, bench_sampler fn, size_t n);

#endif
