/*
** xml.c: text inside SVG files.  One escaping for every picture: the five
** XML specials, so a string is safe both as element text and inside an
** attribute value quoted with either quote character.
*/
#include "report.h"

int report_xml_text(FILE *f, const char *s) {
  for (; *s; s++) {
    const char *e = NULL;
    switch (*s) {
    case '&': e = "&amp;"; break;
    case '<': e = "&lt;"; break;
    case '>': e = "&gt;"; break;
    case '"': e = "&quot;"; break;
    case '\'': e = "&apos;"; break;
    default: break;
    }
    if ((e != NULL ? fputs(e, f) : fputc(*s, f)) == EOF) return -1;
  }
  return 0;
}
