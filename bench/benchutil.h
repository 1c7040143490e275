/*
** benchutil.h: what every benchmark of bench/ needs besides the code it
** times: wall and CPU clocks, the median of repeated runs, and the load
** average printed beside the figures.  One home, so that every table in
** the README is measured the same way.
*/
#ifndef FLIPLAB_BENCHUTIL_H
#define FLIPLAB_BENCHUTIL_H

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

#endif
