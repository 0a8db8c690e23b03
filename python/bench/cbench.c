/* cbench.c -- the C side of python/bench/bench.py: the same work as a
   vectorised Python call, as a plain C loop over the library's function,
   timed here.

     cbench KIND FILE N REPEATS [L0 Delta]

   reads N rows of doubles from FILE (written by bench.py; the columns of
   KIND below), runs the loop REPEATS times and prints one line per repeat:
   the nanoseconds per element.  A checksum of the results goes to stderr
   (so that the loop is not optimised away).

     sigma4   L0 Delta                  chaplygin_discrete_sigma4 (dir +1)
     heading  L0 D0 V0 Omega0 D         chaplygin_discrete_heading (closed
                                        form, dtheta and dtau)
     step     dir E H                   chaplygin_discrete_step (request
                                        all) from each state of the system
                                        L0 Delta
     ehn      dir E H                   chaplygin_discrete_step_eh_n, 16
                                        steps from each state
     fate     V Omega                   chaplygin_discrete_fate_phase
                                        (max 100000 collisions)
     scalar   -                         chaplygin_discrete_sigma4 (1, 1/3,
                                        +1) N times: the cost of one call */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "chaplygin.h"

static double
now_ns (void)
{
  struct timespec t;
  clock_gettime (CLOCK_MONOTONIC, &t);
  return (double) t.tv_sec * 1e9 + (double) t.tv_nsec;
}

static double *
read_rows (const char *path, size_t n, size_t cols)
{
  double *x = malloc (n * cols * sizeof *x);
  FILE *f = fopen (path, "rb");
  if (!x || !f || fread (x, sizeof *x, n * cols, f) != n * cols)
    {
      fprintf (stderr, "cbench: cannot read %zu x %zu doubles from %s\n", n,
               cols, path);
      exit (2);
    }
  fclose (f);
  return x;
}

int
main (int argc, char **argv)
{
  if (argc < 5)
    {
      fputs ("usage: cbench KIND FILE N REPEATS [L0 Delta]\n", stderr);
      return 2;
    }
  const char *kind = argv[1];
  size_t n = strtoul (argv[3], NULL, 10);
  int repeats = atoi (argv[4]);
  double L0 = argc > 6 ? atof (argv[5]) : 1.0;
  double Delta = argc > 6 ? atof (argv[6]) : 1.0 / 3.0;
  chaplygin_discrete sys;
  if (chaplygin_discrete_init (&sys, L0, Delta))
    return 2;
  double sum = 0.0;
  int fails = 0;

  if (strcmp (kind, "sigma4") == 0)
    {
      double *x = read_rows (argv[2], n, 2), *out = malloc (n * sizeof *out);
      for (int r = 0; r < repeats; r++)
        {
          double t0 = now_ns ();
          for (size_t i = 0; i < n; i++)
            fails += chaplygin_discrete_sigma4 (x[2 * i], x[2 * i + 1], 1,
                                                &out[i], NULL) != 0;
          printf ("%.6g\n", (now_ns () - t0) / (double) n);
          sum += out[n / 2];
        }
    }
  else if (strcmp (kind, "heading") == 0)
    {
      double *x = read_rows (argv[2], n, 5);
      double *th = malloc (n * sizeof *th), *ta = malloc (n * sizeof *ta);
      for (int r = 0; r < repeats; r++)
        {
          double t0 = now_ns ();
          for (size_t i = 0; i < n; i++)
            {
              const double *q = x + 5 * i;
              fails += chaplygin_discrete_heading (q[0], q[1], q[2], q[3],
                                                   q[4], NULL, &th[i],
                                                   &ta[i]) != 0;
            }
          printf ("%.6g\n", (now_ns () - t0) / (double) n);
          sum += th[n / 2] + ta[n / 2];
        }
    }
  else if (strcmp (kind, "step") == 0 || strcmp (kind, "ehn") == 0)
    {
      int ehn = strcmp (kind, "ehn") == 0;
      double *x = read_rows (argv[2], n, 3);
      chaplygin_discrete_state *in = calloc (n, sizeof *in);
      chaplygin_discrete_state *out = calloc (n, sizeof *out);
      chaplygin_discrete_event *ev = calloc (n, sizeof *ev);
      for (size_t i = 0; i < n; i++)
        {
          in[i].dir = (int) x[3 * i];
          in[i].E = x[3 * i + 1];
          in[i].H = x[3 * i + 2];
        }
      for (int r = 0; r < repeats; r++)
        {
          double t0 = now_ns ();
          if (ehn)
            for (size_t i = 0; i < n; i++)
              {
                out[i] = in[i];
                fails += chaplygin_discrete_step_eh_n (&sys, &out[i], 16,
                                                       NULL) != 0;
              }
          else
            for (size_t i = 0; i < n; i++)
              fails += chaplygin_discrete_step (&sys, &in[i],
                                                CHAPLYGIN_WANT_ALL, NULL,
                                                &out[i], &ev[i]) != 0;
          printf ("%.6g\n", (now_ns () - t0) / (double) n);
          sum += out[n / 2].E;
        }
    }
  else if (strcmp (kind, "fate") == 0)
    {
      double *x = read_rows (argv[2], n, 2);
      chaplygin_fate *f = calloc (n, sizeof *f);
      for (int r = 0; r < repeats; r++)
        {
          double t0 = now_ns ();
          for (size_t i = 0; i < n; i++)
            {
              const double q[4] = { x[2 * i] > 0 ? 0.0 : Delta, x[2 * i],
                                    0.0, x[2 * i + 1] };
              fails += chaplygin_discrete_fate_phase (&sys, q, 100000, NULL,
                                                      0, &f[i]) != 0;
            }
          printf ("%.6g\n", (now_ns () - t0) / (double) n);
          sum += f[n / 2].E_final;
        }
    }
  else if (strcmp (kind, "scalar") == 0)
    {
      volatile double L = 1.0, D = 1.0 / 3.0;
      double out;
      for (int r = 0; r < repeats; r++)
        {
          double t0 = now_ns ();
          for (size_t i = 0; i < n; i++)
            {
              fails += chaplygin_discrete_sigma4 (L, D, 1, &out, NULL) != 0;
              sum += out;
            }
          printf ("%.6g\n", (now_ns () - t0) / (double) n);
        }
    }
  else
    {
      fprintf (stderr, "cbench: unknown kind %s\n", kind);
      return 2;
    }
  fprintf (stderr, "checksum %.17g failures %d\n", sum, fails);
  return 0;
}
