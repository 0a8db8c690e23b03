## examples/local.mk -- examples installed with the documentation.

# A large sweep on a cluster: a Slurm job array of shards and their merge
# (chaplygin sweep --shard, chaplygin merge), runnable without Slurm too;
# tools/test-merge.sh runs them in `make check'.  Installed in
# $(docdir)/examples/slurm.
slurmexamplesdir = $(docdir)/examples/slurm
dist_slurmexamples_DATA = examples/slurm/README examples/slurm/atlas.ini
dist_slurmexamples_SCRIPTS = examples/slurm/atlas.sbatch \
	examples/slurm/merge.sbatch
