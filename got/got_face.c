/*
** got_face.c: the optimal triangulations of one face of a point set's
** skeleton, exactly (got_face.h; docs/got.md, "Point sets: faces with
** points inside").  First commit: the interface only.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "got_face.h"

int got_face_solve(const got_face_in *in, const rule *r, got_face_out *out, char *err,
                   size_t errlen)
{
  (void)in; (void)r;
  memset(out, 0, sizeof *out);
  snprintf(err, errlen, "got_face_solve: not implemented yet");
  return -1;
}

void got_face_out_free(got_face_out *o)
{
  free(o->tri);
  o->tri = NULL;
  o->ntri = 0;
}
