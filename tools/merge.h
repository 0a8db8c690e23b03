/* merge.h -- "chaplygin merge [-o FILE] SHARD.csv...": the outputs of the
   shards of one sweep (chaplygin sweep --shard i/N) joined into the
   output of the whole sweep, with proof that no point is lost or
   repeated (merge.c). */
#ifndef CHAPLYGIN_TOOLS_MERGE_H
#define CHAPLYGIN_TOOLS_MERGE_H

/* ARGV[0 .. ARGC-1] are the words after "merge".  Returns the exit status:
   0; 1 writing failed (or out of memory); 2 a usage error, or an input
   that cannot be read or is refused (not a complete shard of the same
   sweep as the others, a gap, an overlap). */
int merge_main (int argc, char **argv);

#endif
