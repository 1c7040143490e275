/*
** output.c: every file a command writes, written safely.
**
** A failing run must never destroy a good file nor leave a partial one.  So
** cli_open_out does not open the named file: it creates a temporary file in
** the same directory (".NAME.XXXXXX", so that the final rename stays on one
** file system and is atomic) and the command writes there.  Nothing reaches
** the real name until the whole command has succeeded: main() calls
** cli_outputs_finish with the command's status, which on success closes
** every output (checking each flush and close) and renames each temporary
** file over its target, and on failure removes them all.  An interrupted run
** (by any signal whose default action ends the process: SIGINT, SIGTERM,
** SIGQUIT, SIGUSR1, SIGALRM, ...) or an exit() elsewhere removes them too.
**
** Targets that are not regular files (/dev/null, /dev/full, a FIFO, a
** terminal, anything under /dev/ or /proc/) cannot be replaced by a rename;
** they are written directly, still with every write checked.  A symbolic
** link to a file is followed: the file it names is replaced, the link kept.
**
** Standard output ("-") is flushed and closed by cli_outputs_finish too, so
** `fliplab list > /dev/full` fails with a one-line error and status 1.
** Two outputs of one run naming the same file (by name, or by device and
** inode when it exists) are refused: one would silently overwrite the other.
*/
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif
#define CLI_OUT_MAX 4096      /* outputs per run (rule --svg-dir writes many) */

typedef struct cli_out {
  FILE *f;                    /* NULL once closed */
  const char *cmd;
  char *path;                 /* as given, for messages */
  char *final;                /* the file replaced on success (symlinks resolved) */
  char *tmp;                  /* temporary file, or NULL when written directly */
  dev_t dev;                  /* identity of the existing target, if any */
  ino_t ino;
  int exists;
  int failed;                 /* a write, flush or close failed (error printed) */
} cli_out;

/* The table is only appended to, and a slot is filled before the count
** that publishes it, so the signal handler may walk it at any moment. */
static cli_out *volatile cli_outs;
static volatile sig_atomic_t cli_nouts;
static int cli_outs_cap, cli_outs_hooked, cli_stdout_used;
static const char *cli_stdout_cmd = "output";   /* names stdout's errors */

/* Remove every temporary file not yet renamed (async-signal-safe: unlink). */
static void cli_outputs_unlink(void) {
  cli_out *o = cli_outs;
  for (sig_atomic_t i = 0; i < cli_nouts; i++)
    if (o[i].tmp != NULL) unlink(o[i].tmp);
}

static void cli_outputs_on_signal(int sig) {
  cli_outputs_unlink();
  struct sigaction dfl;
  memset(&dfl, 0, sizeof dfl);
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, NULL);
  raise(sig);   /* blocked until the handler returns, then the default action */
}

/* Every signal whose default action ends the process (POSIX's "T" and "A"
** signals, Linux's extras, the real-time ones): an interrupted run removes
** its temporary files whichever of them stops it.  SIGKILL and SIGSTOP
** cannot be caught; the faults (SIGSEGV, SIGBUS, ...) are included, so a
** crash leaves no ".NAME.XXXXXX" either. */
static const int cli_outputs_sigs[] = {
  SIGHUP, SIGINT, SIGQUIT, SIGILL, SIGTRAP, SIGABRT, SIGBUS, SIGFPE, SIGUSR1, SIGSEGV,
  SIGUSR2, SIGPIPE, SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGSYS,
#ifdef SIGSTKFLT
  SIGSTKFLT,
#endif
#ifdef SIGPOLL
  SIGPOLL,
#endif
#ifdef SIGPWR
  SIGPWR,
#endif
#ifdef SIGEMT
  SIGEMT,
#endif
#ifdef SIGLOST
  SIGLOST,
#endif
};

/* Hook sig unless the caller chose to ignore it (nohup) or something else
** already handles it (a sanitizer's report of SIGSEGV): both are left as
** they are.  While the handler runs every signal is blocked, so a second
** one cannot interrupt the walk over the table. */
static void cli_outputs_hook_one(int sig) {
  struct sigaction sa, old;
  if (sigaction(sig, NULL, &old) != 0 || old.sa_handler != SIG_DFL ||
      (old.sa_flags & SA_SIGINFO))
    return;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = cli_outputs_on_signal;
  sigfillset(&sa.sa_mask);
  sigaction(sig, &sa, NULL);
}

static void cli_outputs_hook(void) {
  if (cli_outs_hooked) return;
  cli_outs_hooked = 1;
  atexit(cli_outputs_unlink);
  for (size_t i = 0; i < sizeof cli_outputs_sigs / sizeof cli_outputs_sigs[0]; i++)
    cli_outputs_hook_one(cli_outputs_sigs[i]);
#ifdef SIGRTMIN
  for (int sig = SIGRTMIN; sig <= SIGRTMAX; sig++) cli_outputs_hook_one(sig);
#endif
}

static char *cli_strdup(const char *s) {
  size_t n = strlen(s) + 1;
  char *d = malloc(n);
  if (d != NULL) memcpy(d, s, n);
  return d;
}

/* Written directly rather than through a rename: devices and the like. */
static int cli_out_direct(const char *path, const struct stat *st, int exists) {
  if (strncmp(path, "/dev/", 5) == 0 || strncmp(path, "/proc/", 6) == 0) return 1;
  return exists && !S_ISREG(st->st_mode);
}

/* The directory part of path ("." when there is none) into buf. */
static void cli_out_dir(const char *path, char *buf, size_t len) {
  const char *slash = strrchr(path, '/');
  if (slash == NULL) snprintf(buf, len, ".");
  else if (slash == path) snprintf(buf, len, "/");
  else snprintf(buf, len, "%.*s", (int)(slash - path), path);
}

/* The file a rename must replace, canonical so that two spellings of one
** name compare equal: what a symlink names, else the real directory plus
** the base name.  path itself when the directory does not exist (creating
** the temporary file will then fail with the right message). */
static char *cli_out_target(const char *path) {
  struct stat lst;
  if (lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode)) {
    char *real = realpath(path, NULL);
    if (real != NULL) return real;
  }
  char dir[PATH_MAX];
  cli_out_dir(path, dir, sizeof dir);
  const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
  char *rdir = realpath(dir, NULL);
  if (rdir == NULL || *base == '\0' || strcmp(base, ".") == 0 || strcmp(base, "..") == 0) {
    free(rdir);
    return cli_strdup(path);
  }
  size_t len = strlen(rdir) + strlen(base) + 2;
  char *t = malloc(len);
  if (t != NULL) snprintf(t, len, "%s%s%s", rdir, strcmp(rdir, "/") == 0 ? "" : "/", base);
  free(rdir);
  return t;
}

/* Is this target already an output of the run? */
static const cli_out *cli_out_find(const char *final, const struct stat *st, int exists) {
  for (sig_atomic_t i = 0; i < cli_nouts; i++) {
    const cli_out *o = &cli_outs[i];
    if (strcmp(o->final, final) == 0) return o;
    if (exists && o->exists && o->dev == st->st_dev && o->ino == st->st_ino) return o;
  }
  return NULL;
}

/* A temporary file next to final, with the mode a new file would get (or
** the existing file's).  Its name goes to *tmp. */
static FILE *cli_out_mktemp(const char *cmd, const char *path, const char *final,
                            const struct stat *st, int exists, char **tmp) {
  char dir[PATH_MAX];
  cli_out_dir(final, dir, sizeof dir);
  const char *base = strrchr(final, '/') ? strrchr(final, '/') + 1 : final;
  size_t len = strlen(dir) + strlen(base) + 16;
  *tmp = malloc(len);
  if (*tmp == NULL) {
    cli_error(cmd, "out of memory");
    return NULL;
  }
  snprintf(*tmp, len, "%s/.%s.XXXXXX", dir, base);
  int fd = mkstemp(*tmp);
  if (fd < 0) {
    cli_error(cmd, "cannot write '%.200s': %s", path, strerror(errno));
    free(*tmp);
    *tmp = NULL;
    return NULL;
  }
  mode_t mode;
  if (exists) {
    mode = st->st_mode & 07777;
  } else {
    mode_t mask = umask(0);
    umask(mask);
    mode = 0666 & ~mask;
  }
  (void)fchmod(fd, mode);
  FILE *f = fdopen(fd, "w");
  if (f == NULL) {
    cli_error(cmd, "cannot write '%.200s': %s", path, strerror(errno));
    close(fd);
    unlink(*tmp);
    free(*tmp);
    *tmp = NULL;
  }
  return f;
}

static int cli_outs_grow(const char *cmd) {
  if (cli_nouts < cli_outs_cap) return 0;
  if (cli_outs_cap >= CLI_OUT_MAX) {
    cli_error(cmd, "more than %d output files in one run", CLI_OUT_MAX);
    return -1;
  }
  int cap = cli_outs_cap ? 2 * cli_outs_cap : 8;
  cli_out *n = malloc((size_t)cap * sizeof *n);
  if (n == NULL) {
    cli_error(cmd, "out of memory");
    return -1;
  }
  /* Copy, publish, then free: the signal handler always sees a whole table. */
  if (cli_nouts > 0) memcpy(n, cli_outs, (size_t)cli_nouts * sizeof *n);
  cli_out *old = cli_outs;
  cli_outs = n;
  cli_outs_cap = cap;
  free(old);
  return 0;
}

/* Open o's file (in place, or a temporary beside it) and publish o in the
** table the signal handler reads.  From mkstemp until the entry is
** published the temporary file exists but the handler cannot know it:
** signals are held for that window, so one arriving in it still removes
** the file (a run killed then left it behind). */
static void cli_out_open_published(const char *cmd, cli_out *o, const struct stat *st) {
  sigset_t all, was;
  sigfillset(&all);
  sigprocmask(SIG_BLOCK, &all, &was);
  if (cli_out_direct(o->final, st, o->exists)) {
    o->f = fopen(o->final, "w");
    if (o->f == NULL) cli_error(cmd, "cannot write '%.200s': %s", o->path, strerror(errno));
  } else {
    o->f = cli_out_mktemp(cmd, o->path, o->final, st, o->exists, &o->tmp);
  }
  if (o->f != NULL) {
    cli_outs[cli_nouts] = *o;
    cli_nouts = cli_nouts + 1;
  }
  sigprocmask(SIG_SETMASK, &was, NULL);
}

FILE *cli_open_out(const char *cmd, const char *path) {
  if (path == NULL || strcmp(path, "-") == 0) {
    if (cli_stdout_used) {
      cli_error(cmd, "two outputs go to standard output ('-'); name a file for one of them");
      return NULL;
    }
    cli_stdout_used = 1;
    cli_stdout_cmd = cmd;
    return stdout;
  }
  if (path[0] == '\0') {
    cli_error(cmd, "an output file name is empty");
    return NULL;
  }
  cli_outputs_hook();
  struct stat st;
  int exists = stat(path, &st) == 0;
  char *final = cli_out_target(path);
  if (final == NULL || cli_outs_grow(cmd) != 0) {
    if (final == NULL) cli_error(cmd, "out of memory");
    free(final);
    return NULL;
  }
  const cli_out *dup = cli_out_find(final, &st, exists);
  if (dup != NULL) {
    if (strcmp(dup->path, path) == 0)
      cli_error(cmd, "'%.200s' is named by two outputs; one would overwrite the other", path);
    else
      cli_error(cmd, "'%.200s' and '%.200s' are the same file, named by two outputs; one "
                "would overwrite the other", dup->path, path);
    free(final);
    return NULL;
  }
  cli_out o = {.cmd = cmd, .final = final, .exists = exists};
  if (exists) {
    o.dev = st.st_dev;
    o.ino = st.st_ino;
  }
  o.path = cli_strdup(path);
  if (o.path == NULL) cli_error(cmd, "out of memory");
  else cli_out_open_published(cmd, &o, &st);
  if (o.f == NULL) {
    free(o.path);
    free(final);
    return NULL;
  }
  return o.f;
}

static cli_out *cli_out_of(FILE *f) {
  for (sig_atomic_t i = 0; i < cli_nouts; i++)
    if (cli_outs[i].f == f) return &cli_outs[i];
  return NULL;
}

/* Close o's stream, checking every buffered write; print the one-line
** error on failure unless quiet (another error was printed already). */
static int cli_out_close(cli_out *o, int quiet) {
  if (o->f == NULL) return o->failed ? -1 : 0;
  int bad = ferror(o->f) != 0;
  int e = errno;
  if (fflush(o->f) != 0) {
    bad = 1;
    e = errno;
  }
  if (fclose(o->f) != 0 && !bad) {
    bad = 1;
    e = errno;
  }
  o->f = NULL;
  if (bad && !o->failed) {
    o->failed = 1;
    if (!quiet)
      cli_error(o->cmd, "cannot write '%.200s': %s", o->path, e ? strerror(e) : "write error");
  }
  return bad ? -1 : 0;
}

/* Standard output: flushed and checked (closed only by cli_outputs_finish). */
static int cli_stdout_check(const char *cmd, int quiet) {
  static int reported;
  errno = 0;
  if (fflush(stdout) == 0 && !ferror(stdout)) return 0;
  if (!reported && !quiet)
    cli_error(cmd, "cannot write standard output: %s", errno ? strerror(errno) : "write error");
  reported = 1;
  return -1;
}

int cli_close_out(FILE *f) {
  if (f == NULL) return 0;
  if (f == stdout) return cli_stdout_check(cli_stdout_cmd, 0);
  cli_out *o = cli_out_of(f);
  if (o == NULL) return fclose(f) != 0 ? -1 : 0;   /* not ours: still checked */
  return cli_out_close(o, 0);
}

int cli_finish_out(const char *cmd, FILE *f, int wrc) {
  if (f == NULL) return 0;
  if (cli_close_out(f) != 0) return 1;
  /* The writer failed but the stream did not: it could not allocate. */
  if (wrc != 0) {
    cli_error(cmd, "out of memory");
    return 1;
  }
  return 0;
}

void cli_abort_out(FILE *f) {
  cli_out *o = f == NULL || f == stdout ? NULL : cli_out_of(f);
  if (o == NULL) return;
  fclose(o->f);
  o->f = NULL;
  if (o->tmp != NULL) {      /* never renamed: the old file stays as it was */
    unlink(o->tmp);
    char *t = o->tmp;
    o->tmp = NULL;
    free(t);
  }
}

static void cli_outputs_free(void) {
  for (sig_atomic_t i = 0; i < cli_nouts; i++) {
    free(cli_outs[i].path);
    free(cli_outs[i].final);
    free(cli_outs[i].tmp);
  }
  cli_nouts = 0;
  free(cli_outs);
  cli_outs = NULL;
  cli_outs_cap = 0;
}

int cli_outputs_finish(const char *cmd, int status) {
  int ok = status == 0;
  for (sig_atomic_t i = 0; i < cli_nouts; i++)
    if (cli_out_close(&cli_outs[i], !ok) != 0) ok = 0;
  if (cli_stdout_check(cmd, !ok) != 0) ok = 0;
  for (sig_atomic_t i = 0; i < cli_nouts; i++) {
    cli_out *o = &cli_outs[i];
    if (o->tmp == NULL) continue;
    if (ok && rename(o->tmp, o->final) != 0) {
      cli_error(cmd, "cannot replace '%.200s': %s", o->path, strerror(errno));
      ok = 0;
    }
    if (!ok) unlink(o->tmp);
    char *t = o->tmp;       /* unpublished before it is freed: the handler walks it */
    o->tmp = NULL;
    free(t);
  }
  cli_outputs_free();
  /* Close stdout last so a deferred error (NFS, quota) is not lost. */
  if (fclose(stdout) != 0 && ok) {
    cli_error(cmd, "cannot write standard output: %s", strerror(errno));
    ok = 0;
  }
  return ok ? 0 : status != 0 ? status : 1;
}
