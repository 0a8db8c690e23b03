/* report.c -- what the scene engine says back (chaplygin_scene_report):
   statuses, messages, the row limit; and the C locale its numbers are
   read and written in. */
#include <config.h>

#include <locale.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "chaplygin-scene.h"
#include "engine.h"

const char *
chaplygin_scene_strerror (int status)
{
  switch (status)
    {
    case CHAPLYGIN_SCENE_OK:
      return "success";
    case CHAPLYGIN_SCENE_EINVAL:
      return "invalid argument";
    case CHAPLYGIN_SCENE_EIO:
      return "the scene cannot be read";
    case CHAPLYGIN_SCENE_ESCENE:
      return "not a valid scene";
    case CHAPLYGIN_SCENE_EMODEL:
      return "the model rejects the scene";
    case CHAPLYGIN_SCENE_ELIMIT:
      return "more rows than max_rows";
    case CHAPLYGIN_SCENE_ERUN:
      return "the library failed during the run";
    case CHAPLYGIN_SCENE_ESTOPPED:
      return "stopped by the caller";
    case CHAPLYGIN_SCENE_ENOMEM:
      return "out of memory";
    default:
      return "unknown status";
    }
}

void
report_clear (chaplygin_scene_report *rep)
{
  if (!rep)
    return;
  memset (rep, 0, sizeof *rep);
  rep->collision = -1;
}

int
report_fail (chaplygin_scene_report *rep, int status, const char *fmt, ...)
{
  va_list ap;
  if (!rep || rep->status != CHAPLYGIN_SCENE_OK)
    return status;
  rep->status = status;
  c_locale l;
  int in_c = c_locale_enter (&l) == 0;
  va_start (ap, fmt);
  vsnprintf (rep->message, sizeof rep->message, fmt, ap);
  va_end (ap);
  if (in_c)
    c_locale_leave (&l);
  return status;
}

int
c_snprintf (char *buf, size_t size, const char *fmt, ...)
{
  va_list ap;
  c_locale l;
  int in_c = c_locale_enter (&l) == 0;
  va_start (ap, fmt);
  int n = vsnprintf (buf, size, fmt, ap);
  va_end (ap);
  if (in_c)
    c_locale_leave (&l);
  return n;
}

/* Bytes per number: %.17g is at most 24 characters
   ("-1.2345678901234567e-300"), and a separator. */
#define BYTES_PER_NUMBER 25.0

int
report_limit (chaplygin_scene_report *rep, const char *name,
              const char *what, double rows, int columns, long max_rows,
              const char *hint)
{
  static const char *const units[] = { "bytes", "kB", "MB", "GB", "TB",
                                       "PB", "EB" };
  if (rows <= (double) max_rows)
    return CHAPLYGIN_SCENE_OK;
  double size = rows * columns * BYTES_PER_NUMBER;
  int u = 0;
  while (size >= 1000.0 && u < 6)
    {
      size /= 1000.0;
      u++;
    }
  return report_fail (rep, CHAPLYGIN_SCENE_ELIMIT, "%s: %s would write %.0f "
                      "rows (up to about %.3g %s), more than max_rows = %ld; "
                      "%s", name, what, rows, size, units[u], max_rows,
                      hint);
}

const char *
chaplygin_text_shown (char *buf, size_t size, const char *s, size_t max)
{
  static const char hex[] = "0123456789abcdef";
  size_t i, n = 0;

  for (i = 0; s[i] && i < max && n + 8 < size; i++)
    {
      unsigned char ch = (unsigned char) s[i];
      if (ch < 0x20 || ch == 0x7f)
        {
          buf[n++] = '\\';
          buf[n++] = 'x';
          buf[n++] = hex[ch >> 4];
          buf[n++] = hex[ch & 15];
        }
      else
        buf[n++] = (char) ch;
    }
  if (s[i])
    {
      memcpy (buf + n, "...", 3);
      n += 3;
    }
  buf[n] = '\0';
  return buf;
}

int
c_locale_enter (c_locale *l)
{
  l->c = newlocale (LC_ALL_MASK, "C", (locale_t) 0);
  if (l->c == (locale_t) 0)
    return -1;
  l->saved = uselocale (l->c);
  return 0;
}

void
c_locale_leave (c_locale *l)
{
  uselocale (l->saved);
  freelocale (l->c);
}
