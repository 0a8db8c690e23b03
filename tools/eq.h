/* eq.h -- "chaplygin eq": one numbered equation of the paper evaluated
   at the user's inputs through the library (eq.c). */
#ifndef CHAPLYGIN_TOOLS_EQ_H
#define CHAPLYGIN_TOOLS_EQ_H

/* ARGV[0 .. ARGC-1] are the words after "eq".  Returns the exit status:
   0, 1 (a library failure other than a domain error), 2 (usage: unknown
   label, unknown, missing or malformed input, input outside the domain). */
int eq_main (int argc, char **argv);

#endif /* CHAPLYGIN_TOOLS_EQ_H */
