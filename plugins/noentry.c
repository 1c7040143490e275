/*
** noentry.c: a deliberately broken plugin for the tests: a shared object
** without the fliplab_plugin_entry symbol, to be refused with a one-line error.
*/
double noentry_something(double x);

double noentry_something(double x) {
  return 2 * x;
}
