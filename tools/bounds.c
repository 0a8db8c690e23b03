/* bounds.c -- the row limit and the size estimate (bounds.h). */
#include <config.h>

#include <stdio.h>

#include "bounds.h"

/* Bytes per number: %.17g is at most 24 characters ("-1.2345678901234567e-300"),
   and a separator. */
#define BYTES_PER_NUMBER 25.0

int
bounds_check (const char *path, const char *what, double rows, int columns,
              long max_rows, const char *hint)
{
  static const char *const units[] = { "bytes", "kB", "MB", "GB", "TB",
                                       "PB", "EB" };
  if (rows <= (double) max_rows)
    return 0;
  double size = rows * columns * BYTES_PER_NUMBER;
  int u = 0;
  while (size >= 1000.0 && u < 6)
    {
      size /= 1000.0;
      u++;
    }
  fprintf (stderr, "chaplygin: %s: %s would write %.0f rows (up to about "
           "%.3g %s), more than max_rows = %ld; %s\n", path, what, rows, size,
           units[u], max_rows, hint);
  return -1;
}
