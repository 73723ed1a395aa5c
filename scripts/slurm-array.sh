#!/usr/bin/env bash
# Worked example: the paper-scale suite as a Slurm job array, then one merge.
#
#   sbatch --array=0-15 scripts/slurm-array.sh      # 16 shards, one per array task
#   # when all tasks are done:
#   target/release/mowmill merge results/paper-slurm<JOBID>/shard-*-of-16 --out results/paper-merged
#
# Each task runs `mowmill bench` on its slice of the instance list: mowmill reads
# SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT (made 0-based with SLURM_ARRAY_TASK_MIN) when no
# --shard is given, and names the run after SLURM_ARRAY_JOB_ID so all shards share one run id.
# A task that is killed (time limit, preemption) can be re-submitted with --resume on its
# directory: it skips the rows it already wrote.
#SBATCH --job-name=mowmill
#SBATCH --cpus-per-task=4
#SBATCH --time=04:00:00
#SBATCH --output=mowmill-%A_%a.log
set -euo pipefail
cd "${SLURM_SUBMIT_DIR:-$(dirname "$0")/..}"
cfg=${MOWMILL_CONFIG:-experiments/paper.toml}
count=${SLURM_ARRAY_TASK_COUNT:?run me with sbatch --array}
task=$(( SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-0} ))
out="results/$(basename "$cfg" .toml)-slurm${SLURM_ARRAY_JOB_ID}/shard-${task}-of-${count}"
if [ -f "$out/results.csv" ]; then
  exec target/release/mowmill bench --resume "$out" --shard "${task}/${count}" --jobs "${SLURM_CPUS_PER_TASK:-1}"
fi
exec target/release/mowmill bench --config "$cfg" --out "$out" --shard "${task}/${count}" --jobs "${SLURM_CPUS_PER_TASK:-1}"
