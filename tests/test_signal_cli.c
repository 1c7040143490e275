/*
** test_signal_cli.c: a run stopped by a signal leaves no temporary file and
** the old output intact (cli/output.c).  Each signal whose default action
** ends the process (SIGQUIT, SIGUSR1 and SIGALRM once left ".X.XXXXXX"
** behind) is sent to a long `table34 --out X` run once its temporary file
** exists; the run must die of that very signal (the handler cleans up, then
** the default action happens), with X byte-identical and no ".X.*" left.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"

#define TS_PRECIOUS "precious,content\n1,2\n"
static char ts_dir[512], ts_out[600];

/* Temporary files (".NAME.XXXXXX") in the test directory. */
static int ts_temps(void) {
  DIR *d = opendir(ts_dir);
  assert_non_null(d);
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    n += e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
  closedir(d);
  return n;
}

/* A long table34 run writing ts_out, with default signal actions, nothing
** blocked and no core file (SIGQUIT's default action dumps one). */
static pid_t ts_start(void) {
  pid_t pid = fork();
  assert_true(pid >= 0);
  if (pid > 0) return pid;
  struct rlimit no_core = {0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, NULL);
  for (int s = 1; s < NSIG; s++) signal(s, SIG_DFL);
  if (chdir(ts_dir) != 0) _exit(127);
  execl(FLIPLAB_BIN, "fliplab", "table34", "--samples", "1e11", "--threads", "1", "--out",
        ts_out, (char *)NULL);
  _exit(127);
}

static void ts_sleep_ms(long ms) {
  struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&t, NULL);
}

static void ts_one(int sig) {
  testutil_write_file(ts_out, TS_PRECIOUS);
  assert_int_equal(ts_temps(), 0);
  pid_t pid = ts_start();
  for (int k = 0; k < 2000 && ts_temps() == 0; k++) ts_sleep_ms(5);   /* at most 10 s */
  if (ts_temps() == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
    fail_msg("signal %d: table34 made no temporary file", sig);
  }
  ts_sleep_ms(20);                                   /* into the run proper */
  assert_int_equal(kill(pid, sig), 0);
  int status;
  assert_int_equal(waitpid(pid, &status, 0), pid);
  if (!WIFSIGNALED(status) || WTERMSIG(status) != sig)
    fail_msg("signal %d (%s): the run should die of it, status 0x%x", sig, strsignal(sig),
             status);
  if (ts_temps() != 0) fail_msg("signal %d (%s) left a temporary file", sig, strsignal(sig));
  char *now = testutil_read_file(ts_out);
  assert_non_null(now);
  if (strcmp(now, TS_PRECIOUS) != 0)
    fail_msg("signal %d (%s) changed the old file: '%.100s'", sig, strsignal(sig), now);
  free(now);
}

static void test_signals_clean_up(void **state) {
  (void)state;
  static const int sigs[] = {SIGQUIT, SIGUSR1, SIGALRM, SIGINT,  SIGTERM, SIGHUP,
                             SIGPIPE, SIGUSR2, SIGXCPU, SIGVTALRM, SIGPROF};
  for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) ts_one(sigs[i]);
  ts_one(SIGRTMIN);
  ts_one(SIGRTMAX);
}

/* A signal the caller ignores (nohup) stays ignored: the run goes on. */
static void test_ignored_signal_stays_ignored(void **state) {
  (void)state;
  testutil_write_file(ts_out, TS_PRECIOUS);
  assert_int_equal(ts_temps(), 0);
  /* Ignored before the fork, so that the child never has it otherwise. */
  void (*was)(int) = signal(SIGUSR1, SIG_IGN);
  pid_t pid = fork();
  assert_true(pid >= 0);
  if (pid > 0) signal(SIGUSR1, was);
  if (pid == 0) {
    struct rlimit no_core = {0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    if (chdir(ts_dir) != 0) _exit(127);
    execl(FLIPLAB_BIN, "fliplab", "table34", "--samples", "20000", "--threads", "1", "--out",
          ts_out, (char *)NULL);
    _exit(127);
  }
  for (int k = 0; k < 2000 && ts_temps() == 0; k++) ts_sleep_ms(5);
  kill(pid, SIGUSR1);
  int status;
  assert_int_equal(waitpid(pid, &status, 0), pid);
  assert_true(WIFEXITED(status));
  assert_int_equal(WEXITSTATUS(status), 0);
  assert_int_equal(ts_temps(), 0);
  char *now = testutil_read_file(ts_out);
  assert_non_null(now);
  assert_true(strcmp(now, TS_PRECIOUS) != 0);   /* the new table replaced the old file */
  free(now);
}

static int ts_setup(void **state) {
  (void)state;
  char cmd[1200];
  testutil_tmppath(ts_dir, sizeof ts_dir, "signals");
  snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", ts_dir, ts_dir);
  if (system(cmd) != 0) return -1;
  snprintf(ts_out, sizeof ts_out, "%s/X.txt", ts_dir);
  return 0;
}

static int ts_teardown(void **state) {
  (void)state;
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "rm -rf %s", ts_dir);
  return system(cmd) == 0 ? 0 : -1;
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_signals_clean_up),
    cmocka_unit_test(test_ignored_signal_stays_ignored),
  };
  return cmocka_run_group_tests(tests, ts_setup, ts_teardown);
}
