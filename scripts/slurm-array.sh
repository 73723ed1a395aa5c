#!/usr/bin/env bash
# Worked example: the paper-scale suite as a Slurm job array, then one merge.
#
#   sbatch --array=0-15 scripts/slurm-array.sh      # 16 shards, one per array task
#   # when all tasks are done:
#   target/release/mowmill merge results/paper-slurm<JOBID>/shard-*-of-16 --out results/paper-merged
#
# Each task runs `mowmill bench` on its slice of the instance list: mowmill reads
# SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT (made 0-based with SLURM_ARRAY_TASK_MIN; the
# array must be contiguous, e.g. --array=0-15 or 1-16) and refuses invalid values, records the
# shard in the manifest, and names the run after SLURM_ARRAY_JOB_ID so all shards share one
# run id. `merge` refuses a set of shards that is incomplete, unfinished or mixes configs.
#
# A task that is killed and requeued (`scontrol requeue`, preemption, node failure) runs this
# script again with the same SLURM_* variables: its directory already holds a manifest, so it
# continues with `--resume DIR --config CFG` (the config must be the recorded one, the shard is
# the recorded one), skipping every row it wrote. A lock left by the killed attempt is taken
# over: it names the same SLURM_JOB_ID with a lower SLURM_RESTART_COUNT.
#SBATCH --job-name=mowmill
#SBATCH --cpus-per-task=4
#SBATCH --time=04:00:00
#SBATCH --output=mowmill-%A_%a.log
#SBATCH --requeue
set -euo pipefail
cd "${SLURM_SUBMIT_DIR:-$(dirname "$0")/..}"
cfg=${MOWMILL_CONFIG:-experiments/paper.toml}
count=${SLURM_ARRAY_TASK_COUNT:?run me with sbatch --array}
task=$(( SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-0} ))
out="results/$(basename "$cfg" .toml)-slurm${SLURM_ARRAY_JOB_ID}/shard-${task}-of-${count}"
jobs=${SLURM_CPUS_PER_TASK:-1}
# No --shard: mowmill takes the shard from the SLURM_* variables and checks them.
if [ -f "$out/manifest.json" ]; then
  exec target/release/mowmill bench --resume "$out" --config "$cfg" --jobs "$jobs"
fi
exec target/release/mowmill bench --config "$cfg" --out "$out" --jobs "$jobs"
