/*
** fuzz_tri_measure.c: study_tri_measure (studies/triavg.h) on arbitrary
** triangles.  The first byte chooses N (3 to 34), the rest are vertex
** indices (some past N); N-2 rows are read when the bytes hold them, else
** fewer.  A refusal must be one line; an answer must be a triangulation's:
** interior degrees summing to 2(N-3), n <= T_c <= n(n+1)/2 (the balanced
** and the path recursions bound it), at most N-3 diagonals crossing the
** cut, index lengths between 2 and N/2 each.
*/
#include "fuzz_support.h"
#include "triavg.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  uint32_t nv = 3 + data[0] % 32, tri[3 * 34], deg[34];
  size_t rows = (size - 1) / 3, want = nv - 2;
  if (rows > want + 1) rows = want + 1;          /* one row too many, sometimes */
  for (size_t i = 0; i < 3 * rows; i++) tri[i] = data[1 + i] % (nv + 2);
  study_tri_stats s;
  char err[256] = "";
  if (study_tri_measure(tri, rows, nv, &s, deg, err, sizeof err) != 0) {
    if (err[0] == '\0' || strchr(err, '\n')) abort();
    return 0;
  }
  uint64_t n = nv - 2, sum = 0;
  for (uint32_t v = 0; v < nv; v++) sum += deg[v];
  if (sum != 2 * (n - 1) || s.tc < n || s.tc > n * (n + 1) / 2 || s.cross > n - 1) abort();
  if (s.len_sum < 2 * (n - 1) || s.len_sum > (n - 1) * (nv / 2)) abort();
  return 0;
}
