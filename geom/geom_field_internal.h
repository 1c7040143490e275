/*
** geom_field_internal.h: a structure's fields read by name, from a table
** of names, offsets and types, for the library's results that bindings
** read without mirroring their layout (lot_stats and lot_check_result in
** lot/lot_fields.c, got_result in got/got_result.c; docs/python.md, "How
** the package talks to the library").  One reader for every such table,
** inline: no symbol of its own.  Not installed.
*/
#ifndef FLIPLAB_GEOM_FIELD_INTERNAL_H
#define FLIPLAB_GEOM_FIELD_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef enum geom_field_type {
  GEOM_FIELD_SIZE,      /* size_t */
  GEOM_FIELD_U64,       /* uint64_t */
  GEOM_FIELD_U32,       /* uint32_t */
  GEOM_FIELD_INT,       /* int, and the enums (int-sized: checked where the table is) */
  GEOM_FIELD_DOUBLE,    /* double */
  GEOM_FIELD_OTHER      /* a pointer: read by a verb of the structure's own */
} geom_field_type;

/* One field: its name (the C member's), where it is, its type, and how
** many elements it holds (1, or an array's length, row after row). */
typedef struct geom_field {
  const char *name;
  size_t off;
  geom_field_type type;
  size_t count;
} geom_field;

/* The bytes of one element of type T (a constant expression). */
#define GEOM_FIELD_BYTES(T)                                                              \
  ((T) == GEOM_FIELD_SIZE ? sizeof(size_t) : (T) == GEOM_FIELD_U64 ? sizeof(uint64_t)     \
   : (T) == GEOM_FIELD_U32 ? sizeof(uint32_t) : (T) == GEOM_FIELD_INT ? sizeof(int)       \
   : (T) == GEOM_FIELD_DOUBLE ? sizeof(double) : sizeof(void *))

/* A row of a table for member M of structure S, of elements of type T. */
#define GEOM_FIELD(S, M, T) {#M, offsetof(S, M), T, sizeof(((S *)0)->M) / GEOM_FIELD_BYTES(T)}

/* The row named name of t[0 .. n-1], or NULL.  O(n). */
static inline const geom_field *geom_field_find(const geom_field *t, size_t n,
                                                const char *name) {
  for (size_t k = 0; name != NULL && k < n; k++)
    if (strcmp(t[k].name, name) == 0) return &t[k];
  return NULL;
}

/* Element i of integer field f of the structure at base, as a signed
** 64-bit value: 0, or -1 when f is missing or no integer, i is outside
** it, or the value exceeds INT64_MAX. */
static inline int geom_field_i64(const void *base, const geom_field *f, size_t i, int64_t *out) {
  if (f == NULL || f->type >= GEOM_FIELD_DOUBLE || i >= f->count) return -1;
  const char *at = (const char *)base + f->off + i * GEOM_FIELD_BYTES(f->type);
  size_t z;
  uint64_t u = 0;
  uint32_t w;
  int v;
  switch (f->type) {
  case GEOM_FIELD_SIZE: memcpy(&z, at, sizeof z); u = z; break;
  case GEOM_FIELD_U64: memcpy(&u, at, sizeof u); break;
  case GEOM_FIELD_U32: memcpy(&w, at, sizeof w); u = w; break;
  case GEOM_FIELD_INT: memcpy(&v, at, sizeof v); *out = v; return 0;
  case GEOM_FIELD_DOUBLE: case GEOM_FIELD_OTHER: return -1;
  }
  if (u > (uint64_t)INT64_MAX) return -1;
  *out = (int64_t)u;
  return 0;
}

/* The same as an unsigned 64-bit value, for tables of counts: -1 also for
** a negative int. */
static inline int geom_field_u64(const void *base, const geom_field *f, size_t i, uint64_t *out) {
  if (f == NULL || f->type >= GEOM_FIELD_DOUBLE || i >= f->count) return -1;
  int64_t v;
  if (f->type == GEOM_FIELD_U64) {   /* beyond INT64_MAX too (a budget of 2^64 - 1 flips) */
    memcpy(out, (const char *)base + f->off + i * sizeof *out, sizeof *out);
    return 0;
  }
  if (geom_field_i64(base, f, i, &v) != 0 || v < 0) return -1;
  *out = (uint64_t)v;
  return 0;
}

/* Double field f (element 0): 0, or -1 when f is missing or no double. */
static inline int geom_field_double(const void *base, const geom_field *f, double *out) {
  if (f == NULL || f->type != GEOM_FIELD_DOUBLE) return -1;
  memcpy(out, (const char *)base + f->off, sizeof *out);
  return 0;
}

#endif
