#!/usr/bin/env bash
# The sweep on a real Slurm (ctest label `slurm`; docs/sweeps.md): a 4-configuration sweep of the
# Cornell box runs locally (--jobs 2) and as a Slurm job array; task 1 is requeued mid-solve
# (`scontrol requeue`: Slurm sends it SIGTERM, it checkpoints, and it runs again from there);
# the merged tables must be identical bytes, and task 1's log must show the stop and the resume.
#   tests/slurm/sweep.sh HEMIRAD SOURCE_DIR [KEEP_DIR]   (KEEP_DIR: copy tables, diff and log there)
# Exits 77 (ctest: skipped) with the reason when no Slurm cluster is up: ci/slurm-up starts one.
set -uo pipefail
hemirad=$1 src=$2 keep=${3:-}
skip() { echo "SKIP: $*; ci/slurm-up starts a single-node cluster"; exit 77; }
fail() { echo "FAIL: $*${work:+ (files in $work)}"; exit 1; }
command -v sbatch >/dev/null || skip "Slurm is not installed (no sbatch)"
scontrol ping 2>/dev/null | grep -q UP || skip "slurmctld is not running (scontrol ping)"
sinfo -h -o %T 2>/dev/null | grep -qE 'idle|mixed|alloc' || skip "no Slurm node is up (slurmd)"

work=$(mktemp -d /tmp/hemirad-slurm-test.XXXXXX)  # slurmd runs on this machine: it sees /tmp
say() { echo "$(date -u +%T) $*" | tee -a "$work/steps.txt"; }
trap 'squeue -h -o %i -n hemirad-slurm-test 2>/dev/null | xargs -r scancel' EXIT
cat > "$work/spec.json" <<JSON
{
  "name": "slurm-test",
  "scenes": ["$src/scenes/cornell/cornell.obj"],
  "axes": {"item-subdiv": [0, 2], "item-res": [64, 128]},
  "flags": {"elements": 300, "shots": 400, "shooters-per-pass": 4},
  "resources": {"cpus": 1, "mem": "500M", "time": "00:05:00"},
  "checkpoint_every": 16,
  "metrics": ["shots", "convergence", "radiosity_hash", "objects.floor.mean_radiosity"]
}
JSON
"$hemirad" experiment "$work/spec.json" --out-dir "$work/local" --jobs 2 >/dev/null 2>"$work/local.err" ||
  fail "local run: $(cat "$work/local.err")"
"$hemirad" experiment "$work/spec.json" --slurm "$work/slurm" >/dev/null 2>&1 || fail "writing the job array"
job=$(sbatch --parsable "$work/slurm/sweep.sbatch") || fail "sbatch"
say "submitted job array $job: $(sbatch --version)"

wait_for() {  # wait_for SECONDS DESCRIPTION COMMAND...
  local until=$((SECONDS + $1)) what=$2; shift 2
  until "$@"; do [ $SECONDS -lt $until ] || fail "timed out waiting for $what"; sleep 0.05; done
}
ck=$work/slurm/tasks/0001/checkpoint.ckpt
wait_for 120 "task 1's first checkpoint" test -e "$ck"
[ -e "$work/slurm/tasks/0001/report.json" ] && fail "task 1 finished before it could be requeued"
say "task 1 has checkpointed; scontrol requeue ${job}_1"
scontrol requeue "${job}_1" || fail "scontrol requeue ${job}_1"
# Slurm holds a requeued job back (BeginTime, about 2 minutes); the test lets it start at once.
pending() { squeue -h -j "${job}_1" -o %T 2>/dev/null | grep -q PENDING; }
wait_for 60 "task 1 to be pending again" pending
say "task 1 pending again: scontrol update JobId=${job}_1 StartTime=now"
scontrol update JobId="${job}_1" StartTime=now || fail "scontrol update StartTime=now"
queue_empty() { [ -z "$(squeue -h -j "$job" 2>/dev/null)" ]; }
wait_for 300 "the job array to finish" queue_empty
say "job array $job finished; merging"

"$hemirad" experiment merge "$work/slurm" >/dev/null 2>"$work/merge.err" || fail "merge: $(cat "$work/merge.err")"
log=$work/slurm/logs/task_1.log
diff -u "$work/local/results.csv" "$work/slurm/results.csv" > "$work/results.diff"
same=$?
if [ -n "$keep" ]; then
  mkdir -p "$keep"
  cp "$work/spec.json" "$keep/spec.json"
  cp "$work/local/results.md" "$keep/local_results.md"; cp "$work/local/results.csv" "$keep/local_results.csv"
  cp "$work/slurm/results.md" "$keep/slurm_results.md"; cp "$work/slurm/results.csv" "$keep/slurm_results.csv"
  cp "$work/slurm/sweep.sbatch" "$keep/sweep.sbatch"
  cp "$work/results.diff" "$keep/results.diff"; cp "$log" "$keep/requeue_task_1.log"
  cp "$work/steps.txt" "$keep/steps.txt"
  sed -i "s|$work|\$WORK|g; s|$src|\$SRC|g" "$keep"/*
fi
cat "$log"
[ $same -eq 0 ] || fail "merged tables differ: $(cat "$work/results.diff")"
grep -q "interrupted by SIGTERM" "$log" || fail "task 1's log shows no SIGTERM stop"
grep -q "resuming from its checkpoint at" "$log" || fail "task 1's log shows no resume from its checkpoint"
[ "$(grep -c ',done$' "$work/slurm/results.csv")" -eq 4 ] || fail "not 4 configurations done"
echo "PASS: local and Slurm tables identical ($(wc -l < "$work/slurm/results.csv") lines); task 1 requeued and resumed"
rm -rf "$work"
