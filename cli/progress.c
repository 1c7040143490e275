/*
** progress.c: the stderr progress bar (see cli.h).  Redrawn at most
** ten times a second with a carriage return; erased when the run ends.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <time.h>
#include <unistd.h>
#include "cli.h"

#define CLI_PROGRESS_DELAY 1.0    /* seconds before the bar appears */
#define CLI_PROGRESS_WIDTH 30

static double cli_progress_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_start(cli_progress *p, const char *label) {
  p->enabled = isatty(STDERR_FILENO);
  p->shown = 0;
  p->t0 = p->last = cli_progress_now();
  p->label = label;
  p->open = 0;
}

void cli_progress_update(uint64_t done, uint64_t total, void *ctx) {
  cli_progress *p = ctx;
  if (p == NULL || !p->enabled || total == 0) return;
  double now = cli_progress_now(), el = now - p->t0;
  if (el < CLI_PROGRESS_DELAY || (p->shown && now - p->last < 0.1)) return;
  p->last = now;
  p->shown = 1;
  double frac = done >= total ? 1.0 : (double)done / (double)total;
  int fill = (int)(frac * CLI_PROGRESS_WIDTH);
  char bar[CLI_PROGRESS_WIDTH + 1];
  for (int i = 0; i < CLI_PROGRESS_WIDTH; i++) bar[i] = i < fill ? '#' : '.';
  bar[CLI_PROGRESS_WIDTH] = '\0';
  double eta = frac > 0 ? el * (1 - frac) / frac : 0;
  if (p->open)
    fprintf(stderr, "\r%s [%s] %llu/%llu  %.0fs ", p->label, bar, (unsigned long long)done,
            (unsigned long long)total, el);
  else
    fprintf(stderr, "\r%s [%s] %5.1f%%  %llu/%llu  %.0fs left ", p->label, bar, 100 * frac,
            (unsigned long long)done, (unsigned long long)total, eta);
  fflush(stderr);
}

void cli_progress_finish(cli_progress *p) {
  if (p->shown) {
    fprintf(stderr, "\r%*s\r", 78, "");
    fflush(stderr);
  }
  p->shown = 0;
}
