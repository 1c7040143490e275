/*
** test_geom_key.c: geom/geom_key_internal.h's sorts by a small key against brute force.
** - geom_csr_build: on random keys (some GEOM_CSR_NONE, empty lists, no keys, no items,
**   one key for all) every list holds exactly the items of its key, ascending, and the
**   offsets are the running counts;
** - geom_bucket_sort: the same order as qsort by the full comparison (key, then value).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>
#include "geom_key_internal.h"
#include "splitmix.h"

static size_t tgk_key(const void *ctx, size_t i) { return ((const size_t *)ctx)[i]; }

/* The lists of keys key[0..n-1] among nkeys, checked item by item against a scan. */
static void tgk_csr_check(const size_t *key, size_t n, size_t nkeys) {
  uint32_t *at = malloc((nkeys + 1) * sizeof *at), *idx = malloc((n + 1) * sizeof *idx);
  assert_non_null(at), assert_non_null(idx);
  for (size_t k = 0; k <= nkeys; k++) at[k] = 0xdeadbeef;   /* no zeroing needed */
  geom_csr_build(at, nkeys, idx, n, tgk_key, key);
  size_t listed = 0;
  for (size_t k = 0; k < nkeys; k++) {
    assert_int_equal(at[k], listed);
    for (size_t i = 0; i < n; i++)
      if (key[i] == k) assert_int_equal(idx[listed++], i);   /* ascending: stable */
    assert_int_equal(at[k + 1], listed);
  }
  assert_int_equal(at[nkeys], listed);
  free(at), free(idx);
}

static void test_csr(void **state) {
  (void)state;
  uint64_t s = 12345;
  size_t key[400] = {0};
  tgk_csr_check(key, 0, 0);
  tgk_csr_check(key, 0, 5);
  for (size_t i = 0; i < 7; i++) key[i] = GEOM_CSR_NONE;
  tgk_csr_check(key, 7, 0);
  for (int round = 0; round < 300; round++) {
    size_t n = (size_t)(geom_splitmix64(&s) % 400), nkeys = 1 + geom_splitmix64(&s) % 60;
    int none = round % 3;   /* none, some or many items listed nowhere */
    for (size_t i = 0; i < n; i++) {
      uint64_t u = geom_splitmix64(&s);
      key[i] = u % 4 < (uint64_t)none ? GEOM_CSR_NONE : (size_t)(u >> 8) % nkeys;
    }
    tgk_csr_check(key, n, nkeys);
  }
  for (size_t i = 0; i < 300; i++) key[i] = 2;   /* one list of all, the others empty */
  tgk_csr_check(key, 300, 5);
}

typedef struct tgk_rec { uint32_t key, value; } tgk_rec;

static uint32_t tgk_rec_key(const void *r) { return ((const tgk_rec *)r)->key; }

static int tgk_rec_cmp(const void *x, const void *y) {
  const tgk_rec *a = x, *b = y;
  if (a->key != b->key) return a->key < b->key ? -1 : 1;
  return (a->value > b->value) - (a->value < b->value);
}

static void test_bucket_sort(void **state) {
  (void)state;
  uint64_t s = 777;
  tgk_rec a[500], b[500];
  for (int round = 0; round < 100; round++) {
    size_t n = (size_t)(geom_splitmix64(&s) % 500);
    uint32_t top = (uint32_t)(geom_splitmix64(&s) % (round % 2 ? 8 : 200));   /* big buckets */
    for (size_t i = 0; i < n; i++) {
      uint64_t u = geom_splitmix64(&s);
      a[i] = b[i] = (tgk_rec){(uint32_t)(u % (top + 1)), (uint32_t)(u >> 40)};
    }
    assert_int_equal(geom_bucket_sort(a, n, sizeof *a, top, tgk_rec_key, tgk_rec_cmp), 0);
    qsort(b, n, sizeof *b, tgk_rec_cmp);
    for (size_t i = 0; i < n; i++)
      assert_int_equal(tgk_rec_cmp(a + i, b + i), 0);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_csr),
    cmocka_unit_test(test_bucket_sort),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
