/*
** fuzz_support.h: what the libFuzzer harnesses share: turning the fuzzer's
** bytes into the inputs the readers take (a FILE *, a path, a C string).
*/
#ifndef FLIPLAB_FUZZ_SUPPORT_H
#define FLIPLAB_FUZZ_SUPPORT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The bytes as a read-only stream (fmemopen refuses size 0: use "" then). */
static inline FILE *fuzz_stream(const uint8_t *data, size_t size) {
  static const char empty[1] = "";
  return size ? fmemopen((void *)data, size, "rb") : fmemopen((void *)empty, 1, "r");
}

/* The bytes as a file named by the returned path (one per process, rewritten
** on every call), for readers that take a path. */
static inline const char *fuzz_path(const uint8_t *data, size_t size) {
  static char path[64];
  if (path[0] == '\0') {
    snprintf(path, sizeof path, "/tmp/fliplab-fuzz-%ld.csv", (long)getpid());
  }
  FILE *f = fopen(path, "wb");
  if (f == NULL) abort();
  if (size && fwrite(data, 1, size, f) != size) abort();
  if (fclose(f) != 0) abort();
  return path;
}

/* The bytes as a NUL-terminated string (malloc'ed; caller frees). */
static inline char *fuzz_string(const uint8_t *data, size_t size) {
  char *s = malloc(size + 1);
  if (s == NULL) abort();
  if (size) memcpy(s, data, size);
  s[size] = '\0';
  return s;
}

#endif
