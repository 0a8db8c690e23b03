/* merge.c -- the subcommand "chaplygin merge [-o FILE] SHARD.csv..." (merge.h):
   the outputs of the shards of one sweep joined into the output of the
   whole sweep, with the proof that no point is lost or repeated.

   The output of a shard (chaplygin sweep SCENE.ini --shard i/N, with its
   provenance: csv.c, provenance.c) is
     its header line              k,...
     its provenance lines         # chaplygin VERSION: COMMAND
                                  # scene file: SCENE.ini
                                  # method: ..., # numbers: ... (and so on)
                                  #   the effective scene, line by line
     its rows, k = a .. b         a,...
     its end line, last           # end: complete: N points, k = a .. b of T
                                  (# end: complete: 0 points of T)
   and a sweep that was stopped or failed writes no end line.

   Two passes over the inputs, line by line: the memory used is the
   longest line, the first input's provenance lines and a few numbers per
   input, whatever the number of rows.
   1. Before the output is opened: each input's header and provenance
      lines read and compared with the first input's (the same header
      line, version and effective scene; the command and the scene file's
      name may differ); its last line, read after a seek to its end, its
      end line; the shards sorted by their first k and their ranges
      checked to tile 0 .. T-1, the same T for all (no gap, no overlap).
   2. The output opened (output.h); the header line once; the merge's
      provenance (its command, one line per shard: its range of k, its
      name and its own command line), then the first input's provenance
      lines after its command; the rows of each shard in the order of k,
      each shard's provenance and end line checked again (a file that
      changed between the passes is refused) and each row's k checked to
      be the next one as it is copied; last the end line of the whole
      sweep, in the form of an unsharded run's, so that rows and end line
      are those of "chaplygin sweep SCENE.ini" byte for byte.

   Exit status: 0 success; 1 an output error (or -o FILE cannot be
   created, or out of memory); 2 a usage error, an input that cannot be
   read or is refused. */
#include <config.h>

#include <errno.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "chaplygin-scene.h"
#include "cli.h"
#include "merge.h"
#include "output.h"

enum
{
  EXIT_OK = 0,
  EXIT_OUTPUT = 1,
  EXIT_USAGE = 2
};

/* An input refused, or unreadable: the status of a usage error. */
#define EXIT_INPUT EXIT_USAGE

/* At most this many '#' lines after an input's header line: a sweep
   writes about 30 (its effective scene); more is not a sweep's output. */
#define PROLOGUE_MAX 4096

/* The end line is looked for in this many bytes at an input's end. */
#define TAIL_BYTES 4096

/* At most this many bytes of an input's line are shown in a message. */
#define SHOWN_MAX 160

static const char usage_text[] =
  "Usage: chaplygin merge [-o FILE] SHARD.csv...\n"
  "\n"
  "Join the outputs of the shards of one sweep ('chaplygin sweep SCENE.ini\n"
  "--shard i/N -o SHARD.csv', each with its provenance) into the output of\n"
  "the whole sweep, checking that no point is lost or repeated.  The\n"
  "shards may be named in any order (a glob: shard-*.csv); their rows are\n"
  "written in the order of k.\n"
  "\n"
  "Each SHARD.csv must be a regular file holding a whole shard: the header\n"
  "line, the provenance lines ('#'), the rows and, last, its end line\n"
  "'# end: complete: ...'.  Refused (exit status 2, the file named; -o FILE\n"
  "is then not written):\n"
  "  - an output without provenance (--no-provenance): without the\n"
  "    effective scene and the end line nothing could be checked;\n"
  "  - a header line, a version or an effective scene other than the first\n"
  "    file's (not a shard of the same sweep);\n"
  "  - a shard without its end line (cut short: its sweep was stopped or\n"
  "    failed), with text after it, or with an end line of another kind;\n"
  "  - a gap (points k that no shard has) or an overlap (points that two\n"
  "    shards have), or shards of sweeps of different sizes;\n"
  "  - a row whose k is not the next one (checked while it is copied).\n"
  "The output: the header line; the merge's provenance (its command, one\n"
  "line per shard with its k range and its command) and the first file's\n"
  "provenance lines after its command (the effective scene ...); every row\n"
  "in the order of k; '# end: complete: T points, k = 0 .. T-1 of T'.  Its\n"
  "rows and end line are those of the unsharded sweep, byte for byte.  The\n"
  "shards are read twice (checked, then copied) line by line: the memory\n"
  "used does not grow with their size.\n"
  "\n"
  "Options:\n"
  "  -o, --output FILE  write to FILE ('-': standard output): a temporary\n"
  "                  file beside it, renamed to FILE once everything is\n"
  "                  checked and written; FILE may not be one of the shards\n"
  "  -h, --help      print this text and exit\n"
  "\n"
  "Exit status: 0 success; 1 an output error (or -o FILE cannot be\n"
  "created); 2 a usage error, or a shard that cannot be read or is\n"
  "refused.\n";

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin merge --help' for more information.\n", stderr);
}

/* An input: its name, its place among the operands, its end line. */
typedef struct
{
  const char *name;
  size_t order;
  uint64_t count, a, b, total;  /* N points, k = a .. b of T (N = 0: none) */
} shard;

/* An input read line by line. */
typedef struct
{
  FILE *f;
  const char *name;
  char *buf;                    /* the line, its '\n' included */
  size_t cap;
  size_t len;
  uintmax_t lineno;
  int status;                   /* after a failed read: the exit status */
} reader;

/* The first input's header line and provenance lines. */
typedef struct
{
  const char *name;
  char **line;                  /* line[0]: the header line */
  size_t *len;
  size_t n, cap;
} reference;

/* The line LINE (LEN bytes, its '\n' not shown), cut to SHOWN_MAX bytes,
   into BUF (SHOWN_MAX + 4 bytes) for a message (which shows its control
   bytes: cli_error). */
static const char *
shown (char *buf, const char *line, size_t len)
{
  if (len > 0 && line[len - 1] == '\n')
    len--;
  size_t n = len < SHOWN_MAX ? len : SHOWN_MAX;
  memcpy (buf, line, n);
  strcpy (buf + n, n < len ? "..." : "");
  return buf;
}

/* Open the input NAME into R: a regular file (it is read twice).
   Returns 0, or EXIT_INPUT after a message. */
static int
reader_open (reader *r, const char *name)
{
  struct stat st;
  memset (r, 0, sizeof *r);
  r->name = name;
  if (strcmp (name, "-") == 0)
    {
      cli_error ("merge: '-': a shard must be a file (merge reads each "
                 "shard twice), not standard input");
      return EXIT_INPUT;
    }
  r->f = fopen (name, "re");
  if (!r->f)
    {
      cli_error ("merge: %s: %s", name, strerror (errno));
      return EXIT_INPUT;
    }
  if (fstat (fileno (r->f), &st) != 0 || !S_ISREG (st.st_mode))
    {
      cli_error ("merge: %s: not a regular file (merge reads each shard "
                 "twice)", name);
      fclose (r->f);
      r->f = NULL;
      return EXIT_INPUT;
    }
  return EXIT_OK;
}

static void
reader_close (reader *r)
{
  if (r->f)
    fclose (r->f);
  free (r->buf);
  r->f = NULL;
  r->buf = NULL;
}

/* The next line of R into R->buf.  Returns 1, 0 at the end of the file,
   -1 after a message (R->status: the exit status). */
static int
reader_next (reader *r)
{
  errno = 0;
  ssize_t n = getline (&r->buf, &r->cap, r->f);
  if (n >= 0)
    {
      r->len = (size_t) n;
      r->lineno++;
      return 1;
    }
  if (!ferror (r->f) && errno != ENOMEM)
    return 0;
  if (errno == ENOMEM)
    {
      cli_error ("merge: %s: line %ju: out of memory", r->name,
                 r->lineno + 1);
      r->status = EXIT_OUTPUT;
    }
  else
    {
      cli_error ("merge: %s: error reading: %s", r->name,
                 strerror (errno ? errno : EIO));
      r->status = EXIT_INPUT;
    }
  return -1;
}

/* Whether the LEN bytes of LINE begin with the string PREFIX. */
static int
starts (const char *line, size_t len, const char *prefix)
{
  size_t n = strlen (prefix);
  return len >= n && memcmp (line, prefix, n) == 0;
}

/* The version of the provenance line LINE ("# chaplygin VERSION: ..."):
   its bytes into *V, *VLEN.  0, or -1 if LINE is not such a line. */
static int
version_of (const char *line, size_t len, const char **v, size_t *vlen)
{
  const char *p = "# chaplygin ";
  size_t n = strlen (p);
  if (!starts (line, len, p))
    return -1;
  const char *colon = memchr (line + n, ':', len - n);
  if (!colon || colon == line + n)
    return -1;
  *v = line + n;
  *vlen = (size_t) (colon - (line + n));
  return 0;
}

/* A copy of the line of R appended to REF.  0, or EXIT_OUTPUT after a
   message. */
static int
reference_add (reference *ref, const reader *r)
{
  if (ref->n == ref->cap)
    {
      size_t cap = ref->cap ? 2 * ref->cap : 64;
      char **line = realloc (ref->line, cap * sizeof *line);
      if (line)
        ref->line = line;
      size_t *len = line ? realloc (ref->len, cap * sizeof *len) : NULL;
      if (len)
        ref->len = len;
      if (!line || !len)
        {
          cli_error ("merge: out of memory");
          return EXIT_OUTPUT;
        }
      ref->cap = cap;
    }
  char *copy = malloc (r->len + 1);
  if (!copy)
    {
      cli_error ("merge: out of memory");
      return EXIT_OUTPUT;
    }
  memcpy (copy, r->buf, r->len);
  copy[r->len] = '\0';
  ref->line[ref->n] = copy;
  ref->len[ref->n++] = r->len;
  return EXIT_OK;
}

static void
reference_free (reference *ref)
{
  for (size_t i = 0; i < ref->n; i++)
    free (ref->line[i]);
  free (ref->line);
  free (ref->len);
}

/* The line of R, line I of its header and provenance lines, against line
   I of REF (I < REF->n): the same, but for the version line's command and
   the scene file's name.  0, or EXIT_INPUT after a message. */
static int
compare_line (const reader *r, const reference *ref, size_t i)
{
  const char *line = r->buf, *want = ref->line[i];
  size_t len = r->len, wlen = ref->len[i];
  char s1[SHOWN_MAX + 4], s2[SHOWN_MAX + 4];
  if (i == 1)
    {
      const char *v, *w;
      size_t vlen, wvlen;
      if (version_of (line, len, &v, &vlen) != 0)
        goto differ;
      (void) version_of (want, wlen, &w, &wvlen);
      if (vlen != wvlen || memcmp (v, w, vlen) != 0)
        {
          cli_error ("merge: %s: written by chaplygin %.*s, %s by chaplygin "
                     "%.*s: the shards of one sweep must come from one "
                     "version of the program", r->name, (int) vlen, v,
                     ref->name, (int) wvlen, w);
          return EXIT_INPUT;
        }
      return EXIT_OK;
    }
  if (starts (line, len, "# scene file: ")
      && starts (want, wlen, "# scene file: "))
    return EXIT_OK;
  if (len == wlen && memcmp (line, want, len) == 0)
    return EXIT_OK;
differ:
  if (i == 0)
    cli_error ("merge: %s: its header line '%s' differs from that of %s, "
               "'%s': not a shard of the same sweep", r->name,
               shown (s1, line, len), ref->name, shown (s2, want, wlen));
  else if (starts (line, len, "#   ") || starts (want, wlen, "#   "))
    cli_error ("merge: %s: its effective scene differs from that of %s "
               "(line %ju: '%s', where %s has '%s'): not a shard of the "
               "same sweep", r->name, ref->name, r->lineno,
               shown (s1, line, len), ref->name, shown (s2, want, wlen));
  else
    cli_error ("merge: %s: its provenance differs from that of %s (line "
               "%ju: '%s', where %s has '%s'): not a shard of the same "
               "sweep", r->name, ref->name, r->lineno,
               shown (s1, line, len), ref->name, shown (s2, want, wlen));
  return EXIT_INPUT;
}

/* The provenance that REF (the first input's, just read) must have: a
   version line, the scene file's name and the effective scene.  0, or
   EXIT_INPUT after a message. */
static int
check_reference (const reference *ref)
{
  const char *v;
  size_t vlen;
  int scene = 0, file = 0;
  for (size_t i = 2; i < ref->n; i++)
    {
      scene |= starts (ref->line[i], ref->len[i], "#   ");
      file |= starts (ref->line[i], ref->len[i], "# scene file: ");
    }
  if (version_of (ref->line[1], ref->len[1], &v, &vlen) == 0 && scene
      && file)
    return EXIT_OK;
  cli_error ("merge: %s: its '#' lines are not the provenance of a sweep "
             "(a version line '# chaplygin VERSION: COMMAND', '# scene "
             "file:' and the effective scene '#   ...')", ref->name);
  return EXIT_INPUT;
}

/* The header line and the provenance lines of R, into REF if it is empty
   (R: the first input), else checked against it.  On success R->buf holds
   the line after them, and *MORE is 1 (0: the file ends there).  Returns
   0, or the exit status after a message. */
static int
read_prologue (reader *r, reference *ref, int *more)
{
  char s1[SHOWN_MAX + 4];
  int building = ref->n == 0, got = reader_next (r), rc;
  size_t i = 0;
  if (got < 0)
    return r->status;
  if (got == 0)
    {
      cli_error ("merge: %s: empty: not the output of a sweep", r->name);
      return EXIT_INPUT;
    }
  if (!starts (r->buf, r->len, "k,") || r->buf[r->len - 1] != '\n')
    {
      cli_error ("merge: %s: line 1 '%s' is not the header line of a sweep "
                 "(k,...)", r->name, shown (s1, r->buf, r->len));
      return EXIT_INPUT;
    }
  if (building)
    ref->name = r->name;
  do
    {
      if (i > PROLOGUE_MAX)
        {
          cli_error ("merge: %s: more than %d '#' lines after the header "
                     "line: not the output of a sweep", r->name,
                     PROLOGUE_MAX);
          return EXIT_INPUT;
        }
      if (building)
        rc = reference_add (ref, r);
      else if (i < ref->n)
        rc = compare_line (r, ref, i);
      else
        {
          cli_error ("merge: %s: its provenance differs from that of %s "
                     "(line %ju: '%s' is not in that of %s): not a shard "
                     "of the same sweep", r->name, ref->name, r->lineno,
                     shown (s1, r->buf, r->len), ref->name);
          rc = EXIT_INPUT;
        }
      if (rc != EXIT_OK)
        return rc;
      i++;
    }
  while ((got = reader_next (r)) > 0 && r->buf[0] == '#'
         && !starts (r->buf, r->len, "# end:"));
  if (got < 0)
    return r->status;
  *more = got;
  if (i == 1)
    {
      cli_error ("merge: %s: no provenance ('#' lines) after its header "
                 "line, as written with --no-provenance: merge needs them, "
                 "the effective scene to check that the shards are parts "
                 "of one sweep and the '# end:' line that each is whole",
                 r->name);
      return EXIT_INPUT;
    }
  if (building)
    return check_reference (ref);
  if (i < ref->n)
    {
      cli_error ("merge: %s: its provenance differs from that of %s (it "
                 "ends at line %ju, where %s goes on with '%s'): not a "
                 "shard of the same sweep", r->name, ref->name, r->lineno,
                 ref->name, shown (s1, ref->line[i], ref->len[i]));
      return EXIT_INPUT;
    }
  return EXIT_OK;
}

/* The end line LINE (LEN bytes, from "# end: " to its '\n') of the input
   NAME into *S.  0, or EXIT_INPUT after a message. */
static int
parse_end (const char *name, const char *line, size_t len, shard *s)
{
  char text[600], canon[600], s1[SHOWN_MAX + 4];
  const size_t skip = strlen ("# end: ");
  uint64_t c = 0, a = 0, b = 0, t = 0;
  int ok = 0;
  if (len > skip && line[len - 1] == '\n' && len - skip - 1 < sizeof text
      && !memchr (line, '\0', len))
    {
      memcpy (text, line + skip, len - skip - 1);
      text[len - skip - 1] = '\0';
      if (strncmp (text, "complete: ", 10) != 0)
        {
          cli_error ("merge: %s: the shard is not complete: its end line "
                     "is '%s'", name, shown (s1, line, len));
          return EXIT_INPUT;
        }
      if (sscanf (text, "complete: %" SCNu64 " points, k = %" SCNu64 " .. %"
                  SCNu64 " of %" SCNu64, &c, &a, &b, &t) == 4)
        {
          snprintf (canon, sizeof canon, "complete: %" PRIu64 " points, k = "
                    "%" PRIu64 " .. %" PRIu64 " of %" PRIu64, c, a, b, t);
          ok = strcmp (canon, text) == 0 && c > 0 && a <= b
            && b - a == c - 1 && b < t;
        }
      else if (sscanf (text, "complete: 0 points of %" SCNu64, &t) == 1)
        {
          snprintf (canon, sizeof canon, "complete: 0 points of %" PRIu64, t);
          ok = strcmp (canon, text) == 0;
          c = a = b = 0;
        }
    }
  if (!ok)
    {
      cli_error ("merge: %s: its end line '%s' is not that of a shard of a "
                 "sweep ('# end: complete: N points, k = a .. b of T')",
                 name, shown (s1, line, len));
      return EXIT_INPUT;
    }
  s->count = c;
  s->a = a;
  s->b = b;
  s->total = t;
  return EXIT_OK;
}

/* The end line of R, its last line, read after a seek to its end, into
   *S.  0, or the exit status after a message. */
static int
read_end (reader *r, shard *s)
{
  char tail[TAIL_BYTES + 1], s1[SHOWN_MAX + 4];
  struct stat st;
  if (fstat (fileno (r->f), &st) != 0)
    {
      cli_error ("merge: %s: %s", r->name, strerror (errno));
      return EXIT_INPUT;
    }
  off_t from = st.st_size > TAIL_BYTES ? st.st_size - TAIL_BYTES : 0;
  size_t want = (size_t) (st.st_size - from);
  errno = 0;
  if (fseeko (r->f, from, SEEK_SET) != 0
      || fread (tail, 1, want, r->f) != want)
    {
      cli_error ("merge: %s: error reading its end: %s", r->name,
                 errno ? strerror (errno) : "the file became shorter");
      return EXIT_INPUT;
    }
  if (want == 0 || tail[want - 1] != '\n')
    {
      cli_error ("merge: %s: its last line has no line end: the shard was "
                 "cut short (its sweep stopped, or a full disk)", r->name);
      return EXIT_INPUT;
    }
  tail[want] = '\0';
  const char *start = tail + want - 1;
  while (start > tail && start[-1] != '\n')
    start--;
  size_t len = (size_t) (tail + want - start);
  if ((start == tail && from > 0) || !starts (start, len, "# end: "))
    {
      cli_error ("merge: %s: no '# end:' line at its end (its last line: "
                 "'%s'): the shard was cut short (a sweep that is stopped "
                 "or fails writes none)", r->name, shown (s1, start, len));
      return EXIT_INPUT;
    }
  return parse_end (r->name, start, len, s);
}

/* Shards in the order of their first k, those without points first, then
   in the order given. */
static int
shard_order (const void *x, const void *y)
{
  const shard *s = x, *t = y;
  if ((s->count > 0) != (t->count > 0))
    return s->count > 0 ? 1 : -1;
  if (s->count > 0 && s->a != t->a)
    return s->a < t->a ? -1 : 1;
  return s->order < t->order ? -1 : s->order > t->order;
}

/* The N shards S, sorted, tile 0 .. T-1 (T: their common total) exactly.
   0, or EXIT_INPUT after a message naming a gap or an overlap. */
static int
check_tiling (const shard *s, size_t n)
{
  uint64_t next = 0, total = s[0].total;
  const shard *prev = NULL;
  for (size_t i = 0; i < n; i++)
    {
      if (s[i].count == 0)
        continue;
      if (s[i].a > next)
        {
          if (prev)
            cli_error ("merge: a gap: no shard has the points k = %" PRIu64
                       " .. %" PRIu64 " of %" PRIu64 ", between %s (k = %"
                       PRIu64 " .. %" PRIu64 ") and %s (k = %" PRIu64 " .. %"
                       PRIu64 "): a shard is missing", next, s[i].a - 1,
                       total, prev->name, prev->a, prev->b, s[i].name,
                       s[i].a, s[i].b);
          else
            cli_error ("merge: a gap: no shard has the points k = %" PRIu64
                       " .. %" PRIu64 " of %" PRIu64 ", before %s (k = %"
                       PRIu64 " .. %" PRIu64 "): a shard is missing", next,
                       s[i].a - 1, total, s[i].name, s[i].a, s[i].b);
          return EXIT_INPUT;
        }
      if (s[i].a < next)
        {
          uint64_t last = s[i].b < next - 1 ? s[i].b : next - 1;
          cli_error ("merge: an overlap: %s (k = %" PRIu64 " .. %" PRIu64
                     ") and %s (k = %" PRIu64 " .. %" PRIu64 ") both have "
                     "the points k = %" PRIu64 " .. %" PRIu64 ": a shard "
                     "given twice, or shards of two different splits",
                     prev->name, prev->a, prev->b, s[i].name, s[i].a, s[i].b,
                     s[i].a, last);
          return EXIT_INPUT;
        }
      next = s[i].b + 1;
      prev = &s[i];
    }
  if (next < total)
    {
      if (prev)
        cli_error ("merge: a gap: no shard has the points k = %" PRIu64
                   " .. %" PRIu64 " of %" PRIu64 ", after %s (k = %" PRIu64
                   " .. %" PRIu64 "): a shard is missing", next, total - 1,
                   total, prev->name, prev->a, prev->b);
      else
        cli_error ("merge: a gap: no shard has any of the %" PRIu64
                   " points: the shards given have none", total);
      return EXIT_INPUT;
    }
  return EXIT_OK;
}

/* Pass 1: every input's header, provenance and end line into REF and S
   (N inputs NAMES); then sorted and checked to tile.  0, or the exit
   status after a message. */
static int
survey (char **names, size_t n, reference *ref, shard *s)
{
  for (size_t i = 0; i < n; i++)
    {
      reader r;
      int more, rc = reader_open (&r, names[i]);
      if (rc != EXIT_OK)
        return rc;
      s[i].name = names[i];
      s[i].order = i;
      rc = read_prologue (&r, ref, &more);
      if (rc == EXIT_OK)
        rc = read_end (&r, &s[i]);
      reader_close (&r);
      if (rc != EXIT_OK)
        return rc;
      if (s[i].total != s[0].total)
        {
          cli_error ("merge: %s: a shard of a sweep of %" PRIu64 " points, "
                     "%s of one of %" PRIu64 ": not shards of the same "
                     "sweep", s[i].name, s[i].total, s[0].name, s[0].total);
          return EXIT_INPUT;
        }
    }
  qsort (s, n, sizeof *s, shard_order);
  return check_tiling (s, n);
}

/* The write error on OUT, said.  Returns EXIT_OUTPUT. */
static int
write_error (const output *out)
{
  cli_error ("error writing to %s: %s", out->name,
             strerror (errno ? errno : EIO));
  return EXIT_OUTPUT;
}

/* The provenance line of the shard S into OUT: "# shard k = a .. b
   (NAME): " and the shard's own version line after its "# ".  0, or the
   exit status after a message. */
static int
write_shard_line (output *out, const shard *s)
{
  char name[4 * 1024 + 8];
  reader r;
  int got = 0, rc = reader_open (&r, s->name);
  if (rc != EXIT_OK)
    return rc;
  for (int i = 0; i < 2 && (got = reader_next (&r)) > 0; i++)
    ;
  if (got <= 0 || !starts (r.buf, r.len, "# chaplygin ")
      || r.buf[r.len - 1] != '\n')
    {
      if (got >= 0)
        cli_error ("merge: %s: changed since it was first read (line 2 is "
                   "no longer its version line)", s->name);
      reader_close (&r);
      return got < 0 ? r.status : EXIT_INPUT;
    }
  chaplygin_text_shown (name, sizeof name, s->name, 1024);
  errno = 0;
  if (s->count > 0)
    rc = fprintf (out->stream, "# shard k = %" PRIu64 " .. %" PRIu64
                  " (%s): ", s->a, s->b, name) < 0;
  else
    rc = fprintf (out->stream, "# shard without points (%s): ", name) < 0;
  if (rc || fwrite (r.buf + 2, 1, r.len - 2, out->stream) != r.len - 2)
    rc = write_error (out);
  reader_close (&r);
  return rc;
}

/* The rows of the shard S copied to OUT, its k checked row by row, its
   provenance against REF and its end line against S again.  0, or the
   exit status after a message. */
static int
copy_shard (output *out, const shard *s, reference *ref)
{
  char want[32], s1[SHOWN_MAX + 4];
  reader r;
  shard e;
  int more = 0, rc = reader_open (&r, s->name);
  if (rc != EXIT_OK)
    return rc;
  rc = read_prologue (&r, ref, &more);
  uint64_t k = s->a, end = s->a + s->count;
  size_t wlen = (size_t) snprintf (want, sizeof want, "%" PRIu64 ",", k);
  while (rc == EXIT_OK && more > 0 && r.buf[0] != '#')
    {
      if (r.buf[r.len - 1] != '\n')
        {
          cli_error ("merge: %s: line %ju has no line end: the shard was cut "
                     "short", r.name, r.lineno);
          rc = EXIT_INPUT;
        }
      else if (k == end)
        {
          cli_error ("merge: %s: line %ju: a row '%s' after the last point "
                     "of its end line, k = %" PRIu64, r.name, r.lineno,
                     shown (s1, r.buf, r.len), s->b);
          rc = EXIT_INPUT;
        }
      else if (r.len < wlen || memcmp (r.buf, want, wlen) != 0)
        {
          cli_error ("merge: %s: line %ju: the row '%s' where the next row "
                     "must have k = %" PRIu64 " (a row lost, repeated or out "
                     "of order)", r.name, r.lineno, shown (s1, r.buf, r.len),
                     k);
          rc = EXIT_INPUT;
        }
      else
        {
          errno = 0;
          if (fwrite (r.buf, 1, r.len, out->stream) != r.len)
            rc = write_error (out);
          k++;
          wlen = (size_t) snprintf (want, sizeof want, "%" PRIu64 ",", k);
          if (rc == EXIT_OK && (more = reader_next (&r)) < 0)
            rc = r.status;
        }
    }
  if (rc == EXIT_OK && more == 0)
    {
      cli_error ("merge: %s: no '# end:' line after its last row (line "
                 "%ju): the shard was cut short, or it changed since it was "
                 "first read", r.name, r.lineno);
      rc = EXIT_INPUT;
    }
  else if (rc == EXIT_OK && !starts (r.buf, r.len, "# end: "))
    {
      cli_error ("merge: %s: line %ju: a '#' line among the rows, '%s'",
                 r.name, r.lineno, shown (s1, r.buf, r.len));
      rc = EXIT_INPUT;
    }
  else if (rc == EXIT_OK
           && (rc = parse_end (r.name, r.buf, r.len, &e)) == EXIT_OK
           && (e.count != s->count || e.a != s->a || e.b != s->b
               || e.total != s->total))
    {
      cli_error ("merge: %s: line %ju: its end line '%s' is not the one "
                 "read first: it changed since", r.name, r.lineno,
                 shown (s1, r.buf, r.len));
      rc = EXIT_INPUT;
    }
  else if (rc == EXIT_OK && k != end)
    {
      cli_error ("merge: %s: line %ju: its end line says k = %" PRIu64
                 " .. %" PRIu64 ", but its rows end at k = %" PRIu64
                 " (rows lost)", r.name, r.lineno, s->a, s->b, k - 1);
      rc = EXIT_INPUT;
    }
  if (rc == EXIT_OK && (more = reader_next (&r)) != 0)
    {
      if (more > 0)
        cli_error ("merge: %s: line %ju: text after its '# end:' line",
                   r.name, r.lineno);
      rc = more > 0 ? EXIT_INPUT : r.status;
    }
  reader_close (&r);
  return rc;
}

/* Pass 2: the merged output of the N sorted shards S (provenance REF)
   into OUT.  0, or the exit status after a message. */
static int
write_merged (output *out, const shard *s, size_t n, reference *ref)
{
  char command[1024];
  uint64_t total = s[0].total;
  int rc = EXIT_OK;
  errno = 0;
  if (fwrite (ref->line[0], 1, ref->len[0], out->stream) != ref->len[0]
      || fprintf (out->stream, "# chaplygin %s: %s\n", PACKAGE_VERSION,
                  chaplygin_text_shown (command, sizeof command,
                                        cli_command (), sizeof command)) < 0
      || fprintf (out->stream, "# merged from %zu shard%s, in the order of "
                  "k, each checked whole, together k = 0 .. %" PRIu64
                  " once each:\n", n, n == 1 ? "" : "s",
                  total > 0 ? total - 1 : 0) < 0)
    return write_error (out);
  for (size_t i = 0; i < n && rc == EXIT_OK; i++)
    rc = write_shard_line (out, &s[i]);
  errno = 0;
  for (size_t i = 2; i < ref->n && rc == EXIT_OK; i++)
    if (fwrite (ref->line[i], 1, ref->len[i], out->stream) != ref->len[i])
      rc = write_error (out);
  for (size_t i = 0; i < n && rc == EXIT_OK; i++)
    rc = copy_shard (out, &s[i], ref);
  if (rc != EXIT_OK)
    return rc;
  errno = 0;
  if ((total > 0
       ? fprintf (out->stream, "# end: complete: %" PRIu64 " points, k = 0 .. %"
                  PRIu64 " of %" PRIu64 "\n", total, total - 1, total)
       : fprintf (out->stream, "# end: complete: 0 points of 0\n")) < 0)
    return write_error (out);
  return EXIT_OK;
}

int
merge_main (int argc, char **argv)
{
  const char *output_name = NULL;
  char **names = malloc ((size_t) (argc > 0 ? argc : 1) * sizeof *names);
  size_t n = 0;
  int i = 0, only_operands = 0, rc = -1;
  if (!names)
    {
      cli_error ("merge: out of memory");
      return EXIT_OUTPUT;
    }
  while (i < argc && rc < 0)
    {
      const char *arg = argv[i++], *value;
      int m;
      if (!only_operands && strcmp (arg, "--") == 0)
        only_operands = 1;
      else if (!only_operands && (strcmp (arg, "--help") == 0
                                  || strcmp (arg, "-h") == 0))
        {
          fputs (usage_text, stdout);
          rc = cli_finish_stdout ();
        }
      else if (!only_operands && arg[0] == '-' && arg[1] != '\0')
        {
          if ((m = cli_option ("merge", "--output", "-o", argc, argv, &i,
                               &value)) > 0)
            output_name = value;
          else
            {
              if (m == 0)
                {
                  cli_error ("merge: unknown option '%s'", arg);
                  usage_hint ();
                }
              rc = EXIT_USAGE;
            }
        }
      else
        names[n++] = argv[i - 1];
    }
  if (rc < 0 && n == 0)
    {
      cli_error ("merge: no shard files");
      usage_hint ();
      rc = EXIT_USAGE;
    }
  if (rc >= 0)
    {
      free (names);
      return rc;
    }

  reference ref;
  shard *s = calloc (n, sizeof *s);
  memset (&ref, 0, sizeof ref);
  if (!s)
    {
      cli_error ("merge: out of memory");
      rc = EXIT_OUTPUT;
    }
  else
    rc = survey (names, n, &ref, s);
  for (size_t j = 0; j < n && rc == EXIT_OK; j++)
    if (output_is_input (output_name, names[j]))
      {
        cli_error ("%s: refusing to overwrite the input %s with the output",
                   output_name && strcmp (output_name, "-") != 0
                   ? output_name : "standard output", names[j]);
        rc = EXIT_USAGE;
      }
  if (rc == EXIT_OK)
    {
      output out;
      rc = output_open (&out, output_name, NULL);
      if (rc == EXIT_OK)
        {
          rc = write_merged (&out, s, n, &ref);
          if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
            rc = EXIT_OUTPUT;
        }
    }
  reference_free (&ref);
  free (s);
  free (names);
  return rc;
}
