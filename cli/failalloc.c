/*
** failalloc.c: a test build's allocator that fails on request, to prove
** that every allocation failure on the commands' paths ends in a one-line
** "out of memory" error, frees what it holds (ASan's leak check) and never
** turns into a crash or a wrong answer.
**
** Compiled only with -DFLIPLAB_FAILALLOC=ON, which links the program with
** -Wl,--wrap for malloc, calloc, realloc and aligned_alloc: every call from
** fliplab's own code (libcsv's buffer too, whose realloc goes through
** reports/) lands here.  FLIPLAB_FAILALLOC=K in the environment fails the
** K-th call (once; later calls succeed again, as after a transient
** shortage); FLIPLAB_FAILALLOC_COUNT=1 prints the number of calls made on
** exit, so a test knows how many K to try (tests/test_failalloc_cli.c).
*/
#ifdef FLIPLAB_FAILALLOC
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t k, size_t n);
void *__real_realloc(void *p, size_t n);
void *__real_aligned_alloc(size_t a, size_t n);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t k, size_t n);
void *__wrap_realloc(void *p, size_t n);
void *__wrap_aligned_alloc(size_t a, size_t n);

static atomic_ulong cli_alloc_calls;
static unsigned long cli_alloc_fail_at;
static atomic_int cli_alloc_ready;

static void cli_alloc_report(void) {
  char buf[64];
  int n = snprintf(buf, sizeof buf, "failalloc: %lu allocations\n",
                   (unsigned long)atomic_load(&cli_alloc_calls));
  if (n > 0) (void)!write(2, buf, (size_t)n);
}

/* Is this call the one to fail?  getenv allocates nothing. */
static int cli_alloc_fails(void) {
  if (!atomic_exchange(&cli_alloc_ready, 1)) {
    const char *k = getenv("FLIPLAB_FAILALLOC"), *c = getenv("FLIPLAB_FAILALLOC_COUNT");
    cli_alloc_fail_at = k != NULL ? strtoul(k, NULL, 10) : 0;
    if (c != NULL && c[0] == '1') atexit(cli_alloc_report);
  }
  unsigned long call = atomic_fetch_add(&cli_alloc_calls, 1) + 1;
  return cli_alloc_fail_at != 0 && call == cli_alloc_fail_at;
}

void *__wrap_malloc(size_t n) {
  return cli_alloc_fails() ? NULL : __real_malloc(n);
}

void *__wrap_calloc(size_t k, size_t n) {
  return cli_alloc_fails() ? NULL : __real_calloc(k, n);
}

void *__wrap_realloc(void *p, size_t n) {
  return cli_alloc_fails() ? NULL : __real_realloc(p, n);
}

void *__wrap_aligned_alloc(size_t a, size_t n) {
  return cli_alloc_fails() ? NULL : __real_aligned_alloc(a, n);
}
#else
typedef int cli_failalloc_unused;   /* ISO C wants a declaration per file */
#endif
