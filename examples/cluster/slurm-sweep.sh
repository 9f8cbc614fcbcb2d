#!/usr/bin/env bash
# A sweep on a Slurm cluster: N array tasks run one shard each
# (`rocking sweep --shard K/N`), then a job that waits for all of them merges
# the shards into one sweep.csv, identical to the unsharded run.
#
#   examples/cluster/slurm-sweep.sh SWEEP.toml N [OUT]      # on the login node
#
# submits both and prints their job ids. Shard K is written to OUT/shards/K
# (OUT defaults to out/<sweep file stem>), the merged file to OUT/sweep.csv.
# The folder must be on a file system the nodes share, and `rocking` on their
# PATH (or ROCKING=/path/to/rocking). Resubmitting one failed task:
#   ROCKING_STAGE=shard sbatch --array=K examples/cluster/slurm-sweep.sh SWEEP.toml N OUT
# then the merge alone:
#   ROCKING_STAGE=merge sbatch examples/cluster/slurm-sweep.sh SWEEP.toml N OUT
#
# Adjust the #SBATCH lines to the cluster (partition, account, time). Each
# task runs its cases on the cores it is given (--cpus-per-task).
#SBATCH --job-name=rocking-sweep
#SBATCH --cpus-per-task=8
#SBATCH --time=01:00:00
#SBATCH --output=rocking-sweep-%A_%a.out
set -euo pipefail

if [ $# -lt 2 ]; then
    echo "usage: $0 SWEEP.toml N [OUT]" >&2
    exit 2
fi
sweep="$1"
shards="$2"
stem="$(basename "$sweep")"
out="${3:-out/${stem%.toml}}"
rocking="${ROCKING:-rocking}"

case "${ROCKING_STAGE:-submit}" in
submit)
    # The array's tasks and the merge run this same script in another stage.
    array=$(ROCKING_STAGE=shard sbatch --parsable --export=ALL --array="1-$shards" "$0" "$sweep" "$shards" "$out")
    array="${array%%;*}"
    merge=$(ROCKING_STAGE=merge sbatch --parsable --export=ALL --dependency="afterok:$array" --cpus-per-task=1 "$0" "$sweep" "$shards" "$out")
    echo "shards: job array $array (1-$shards); merge: job ${merge%%;*} -> $out/sweep.csv"
    ;;
shard)
    k="${SLURM_ARRAY_TASK_ID:?the shard stage runs as a task of a job array}"
    "$rocking" sweep "$sweep" --shard "$k/$shards" --out "$out/shards/$k" --threads "${SLURM_CPUS_PER_TASK:-1}"
    ;;
merge)
    # merge checks that every shard 1..N is there once, from this sweep file, complete.
    dirs=()
    for k in $(seq 1 "$shards"); do
        dirs+=("$out/shards/$k")
    done
    "$rocking" merge "${dirs[@]}" --out "$out"
    ;;
*)
    echo "ROCKING_STAGE must be submit, shard or merge, not ${ROCKING_STAGE}" >&2
    exit 2
    ;;
esac
