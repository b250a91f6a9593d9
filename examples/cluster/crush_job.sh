#!/usr/bin/env bash
# The body of the batch jobs of examples/cluster: runs a deck of the project in its own folder with
# checkpoints, and when the scheduler warns that the wall-time limit is near (the signal the job
# script asks for: Slurm's --signal=B:USR1@300), stops the run, requeues the job and exits; the
# requeued job finds the folder and resumes from the newest checkpoint (-var resume 1).
#   bash crush_job.sh EXAMPLE DECK RUN_DIR [-var NAME VALUE ...]
# EXAMPLE: a folder of examples/ (fontainebleau, penetration); its decks and examples/fontainebleau
# (the shared includes) are copied into RUN_DIR on the first start, and the deck runs in
# RUN_DIR/EXAMPLE. A later start in the same RUN_DIR resumes, and, for the penetration scene, reads
# the chamber the first start prepared (-var reuse 1, where chamber_*.restart exists). After the
# deck ends without error the folder is marked done (.job_done) and a later start does nothing.
# Environment: LIGGGHTS (the binary, default liggghts on the PATH), LAUNCH (the site's MPI
# launcher and its arguments, default srun: it takes the job's ranks), REQUEUE (the command that
# requeues the job, default scontrol requeue $SLURM_JOB_ID), CRUSH_ROOT (the repository, default two
# folders above this script). Writes RUN_DIR/EXAMPLE/screen.txt (every start appended) and the deck's
# outputs there.
set -uo pipefail
[ $# -ge 3 ] || { echo "usage: crush_job.sh EXAMPLE DECK RUN_DIR [-var NAME VALUE ...]" >&2; exit 2; }
example=$1 deck=$2 run_dir=$3
shift 3
root=${CRUSH_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
liggghts=${LIGGGHTS:-liggghts}
read -r -a launch <<< "${LAUNCH:-srun}"
read -r -a requeue <<< "${REQUEUE:-scontrol requeue ${SLURM_JOB_ID:-}}"
[ -d "$root/examples/$example" ] || { echo "crush_job.sh: no examples/$example in $root (CRUSH_ROOT)" >&2; exit 2; }
folder=$run_dir/$example
if [ -f "$folder/.job_done" ]; then
  echo "crush_job.sh: $folder is done already (remove .job_done to run it again)"
  exit 0
fi
resume=()
if [ -f "$folder/.job_started" ]; then
  resume=(-var resume 1)
  ls "$folder"/chamber_*.restart > /dev/null 2>&1 && resume+=(-var reuse 1)
  echo "crush_job.sh: $folder was started before: resuming (${resume[*]})"
else
  mkdir -p "$run_dir"
  cp -r "$root/examples/fontainebleau" "$run_dir/"
  [ "$example" = fontainebleau ] || cp -r "$root/examples/$example" "$run_dir/"
  touch "$folder/.job_started"
fi
cd "$folder" || exit 2
pid=
warned() {
  # the wall-time warning: the checkpoints on disk are what the requeued job resumes from; the run
  # is stopped first so that no rank is killed while it writes one
  echo "crush_job.sh: wall-time warning at $(date): stopping the run and requeueing the job"
  [ -z "$pid" ] || { kill -TERM "$pid" 2> /dev/null; wait "$pid"; }
  "${requeue[@]}"
  exit 0
}
trap warned USR1 TERM
echo "crush_job.sh: $(date): ${launch[*]} $liggghts -in $deck ${resume[*]} $* in $folder" >> screen.txt
"${launch[@]}" "$liggghts" -in "$deck" "${resume[@]}" "$@" -log log.liggghts >> screen.txt 2>&1 &
pid=$!
wait "$pid"
rc=$?
if [ "$rc" -eq 0 ] && ! grep -q '^ERROR' log.liggghts; then
  touch .job_done
  echo "crush_job.sh: $deck ended in $folder"
else
  echo "crush_job.sh: $deck stopped (exit $rc): $folder/screen.txt" >&2
fi
exit "$rc"
