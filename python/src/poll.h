/* poll.h -- how the binding's C loops let Python's signal handlers run
   (Ctrl-C during a long call: KeyboardInterrupt within a fraction of a
   second).  Private to python/src and the generated loops: not part of the
   cffi declarations.

   A loop calls chp_py_poll_stop once per iteration: a countdown, a few
   cycles.  When it reaches zero the clock is read and the countdown's
   length adapted so that the clock is read every 1 to 4 ms whatever an
   iteration costs; every CHP_PY_POLL_PERIOD seconds POLL is called.  POLL
   is Python's chp_py_poll (_core.py), a cffi callback: cffi takes the GIL
   to call it, and the interpreter runs the pending signal handlers on
   entering it; one that raises (KeyboardInterrupt) makes it return
   nonzero, and the loop stops for good.  POLL NULL (a call from a thread
   other than Python's main thread, where no handler runs): never. */
#ifndef CHP_PY_POLL_H
#define CHP_PY_POLL_H

/* Seconds between calls of POLL (a shorter period costs a GIL switch
   more often; a longer one delays the KeyboardInterrupt). */
#define CHP_PY_POLL_PERIOD 0.05

typedef struct
{
  int (*poll) (void);
  unsigned long every, left;   /* iterations between clock reads, to go */
  double checked, polled;      /* seconds: the last clock read, call */
  int stopped;
} chp_py_poller;

void chp_py_poller_init (chp_py_poller *p, int (*poll) (void));
int chp_py_poller_due (chp_py_poller *p);

/* Nonzero when the loop must stop (POLL returned nonzero); an iteration's
   work comes after it. */
static inline int
chp_py_poll_stop (chp_py_poller *p)
{
  return __builtin_expect (--p->left == 0, 0) ? chp_py_poller_due (p)
    : p->stopped;
}

#endif
