/*
** progress.h: a progress bar on stderr for long runs.
**
** It appears only when stderr is a terminal and the run has lasted about a
** second, so quick runs, pipes, logs and tests never see it.
*/
#ifndef FLIPLAB_CLI_PROGRESS_H
#define FLIPLAB_CLI_PROGRESS_H

#include <stdint.h>

typedef struct cli_progress {
  int enabled;          /* stderr is a terminal */
  int shown;            /* the bar has been drawn (needs erasing) */
  double t0;            /* start, seconds */
  double last;          /* last redraw, seconds */
  const char *label;
} cli_progress;

void cli_progress_start(cli_progress *p, const char *label);
/* A flipgraph_progress_fn: ctx is the cli_progress. */
void cli_progress_update(uint64_t done, uint64_t total, void *ctx);
void cli_progress_finish(cli_progress *p);

#endif
