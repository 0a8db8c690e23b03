/* errstream.h -- included before each file of tools/ compiled into the
   Python module (gcc -include): their messages to stderr go to the stream
   chp_py_errstream of the calling thread while chp_py_scene_run runs (a
   memory stream it hands to Python), to the real stderr otherwise.  The
   program's sources stay as they are. */
#ifndef CHP_PY_ERRSTREAM_H
#define CHP_PY_ERRSTREAM_H

#include <config.h>
#include <stdio.h>

extern _Thread_local FILE *chp_py_errstream;

#undef stderr
#define stderr (chp_py_errstream ? chp_py_errstream : (stderr))

#endif
