/*
** select.c: choosing what a long run covers, shared by `table34` and
** `census`: the measure list of --measures and the sample range of
** --shard K/N.
*/
#include <string.h>
#include "cli.h"
#include "measure.h"

#define CLI_MAX_SHARDS 1000000ull

/* --measures: "table34", "all" or NAME,NAME,... into ids[]; count or -1. */
int cli_measure_list(const char *cmd, const char *s, int *ids) {
  if (strcmp(s, "table34") == 0) {
    memcpy(ids, measure_table34, sizeof measure_table34);
    return MEASURE_TABLE34_COUNT;
  }
  if (strcmp(s, "all") == 0) {
    /* The thesis's twenty first, in its order, then the others (beta, d,
    ** sigma, user-defined ones) in registry order. */
    int n = MEASURE_TABLE34_COUNT;
    memcpy(ids, measure_table34, sizeof measure_table34);
    for (int m = 0; m < measure_count() && n < MEASURE_MAX; m++) {
      int listed = 0;
      for (int k = 0; k < MEASURE_TABLE34_COUNT; k++) listed |= measure_table34[k] == m;
      if (!listed) ids[n++] = m;
    }
    return n;
  }
  int n = 0;
  const char *p = s;
  for (;;) {
    const char *comma = strchr(p, ',');
    size_t len = comma ? (size_t)(comma - p) : strlen(p);
    char name[128];
    if (len == 0 || len >= sizeof name) {
      cli_error(cmd, "--measures: empty or too long measure name in '%s'", s);
      return -1;
    }
    memcpy(name, p, len);
    name[len] = '\0';
    int id = measure_find(name);
    if (id < 0) {
      char all[2048];
      const char *near = cli_closest_measure(name);
      measure_names(all, sizeof all);
      if (near != NULL)
        cli_error(cmd, "--measures: unknown measure '%s': did you mean '%s'? (fliplab list)", name,
                  near);
      else
        cli_error(cmd, "--measures: unknown measure '%s' (valid: table34, all, or a list of: %s)",
                  name, all);
      return -1;
    }
    for (int i = 0; i < n; i++)
      if (ids[i] == id) {
        cli_error(cmd, "--measures: '%s' is listed twice", name);
        return -1;
      }
    if (n == MEASURE_MAX) return -1;
    ids[n++] = id;
    if (comma == NULL) break;
    p = comma + 1;
  }
  return n;
}

int cli_parse_shard(const char *cmd, const char *s, uint64_t *k, uint64_t *n) {
  const char *slash = strchr(s, '/');
  char ks[32];
  if (slash == NULL || (size_t)(slash - s) >= sizeof ks) {
    cli_error(cmd, "--shard expects K/N (e.g. 3/8), got '%s'", s);
    return -1;
  }
  memcpy(ks, s, (size_t)(slash - s));
  ks[slash - s] = '\0';
  if (cli_parse_u64(cmd, "--shard N", slash + 1, 1, CLI_MAX_SHARDS, n) != 0 ||
      cli_parse_u64(cmd, "--shard K", ks, 1, CLI_MAX_SHARDS, k) != 0)
    return -1;
  if (*k > *n) {
    cli_error(cmd, "--shard %s: K must be between 1 and N", s);
    return -1;
  }
  return 0;
}
