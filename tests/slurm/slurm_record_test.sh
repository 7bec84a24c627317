#!/usr/bin/env bash
# The Slurm test: a private single-node Slurm cluster runs scripts/slurm_record.sh for real.
#
#   tests/slurm/slurm_record_test.sh OCEANGLOBE WORKDIR
#
# Starts munged, slurmctld and slurmd as root with their own key, configuration, state and
# spool under WORKDIR, on free local ports (proctrack/linuxproc, no cgroups, no accounting), so
# it disturbs no Slurm that may already run on the machine. Then:
#   1. renders a short path single-process (the reference);
#   2. submits it as a job array of 3 tasks plus the dependent encode job, exactly as
#      docs/recording.md shows, and checks every frame equals the reference and the MP4 has
#      them all;
#   3. kills one task hard (SIGKILL) part-way, resubmits it, and checks it finishes with
#      --resume: the frames it had written are kept as they were, the rest are rendered, and
#      all equal the reference.
# Everything it started is stopped on exit, whether the test passed or not. Exit 77 (CTest:
# skipped) only when Slurm cannot run here at all: not root, or slurm-wlm / munge missing.
set -euo pipefail

og=$(realpath "${1:?usage: slurm_record_test.sh OCEANGLOBE WORKDIR}")
work=${2:?usage: slurm_record_test.sh OCEANGLOBE WORKDIR}
src=$(cd "$(dirname "$0")/../.." && pwd)

skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "FAILED: $*" >&2; exit 1; }
say() { echo "[slurm test $(date +%T)] $*"; }

[[ $(id -u) -eq 0 ]] || skip "starting slurmctld, slurmd and munged needs root (CI runs the suite as root)"
for tool in munged slurmctld slurmd sbatch squeue scontrol scancel python3 cmp; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/install-deps.sh installs slurm-wlm and munge)"
done

rm -rf "$work"
mkdir -p "$work"/{state,spool,log,ref,frames,resumed}
work=$(realpath "$work")
# munged's socket lives in a short private directory: socket paths are limited to 107 bytes.
run=$(mktemp -d /tmp/og-slurm.XXXXXX)
chmod 755 "$run"
mkdir -m 700 "$run/key"

# --- teardown: everything started here stops, even on failure -------------------------------
cleanup() {
  local status=$?
  set +e
  if [[ -f $work/slurm.conf ]]; then
    export SLURM_CONF=$work/slurm.conf
    scancel --full --signal=KILL --partition=og >/dev/null 2>&1
    timeout 10 scontrol shutdown >/dev/null 2>&1
  fi
  for pidfile in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [[ -s $pidfile ]] || continue
    pid=$(<"$pidfile")
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null
  done
  # Task processes a hard kill may have orphaned (slurmstepd and what it ran): only ours,
  # found by the binary and the frame directories of this test.
  for pid in $(pgrep -f "$work/" 2>/dev/null); do
    ((pid != $$)) && kill -KILL "$pid" 2>/dev/null
  done
  munged --stop --socket="$run/munge.sock" >/dev/null 2>&1
  if [[ -s $run/munged.pid ]]; then kill -KILL "$(<"$run/munged.pid")" 2>/dev/null; fi
  rm -rf "$run"
  if ((status != 0 && status != 77)); then
    echo "--- logs (kept in $work/log) ---" >&2
    tail -n 20 "$work"/log/*.log "$work"/log/*.out 2>/dev/null >&2
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 143' INT TERM

# Waits up to $1 seconds for the command "${@:2}" to succeed.
wait_for() {
  local deadline=$((SECONDS + $1))
  shift
  until "$@"; do
    ((SECONDS < deadline)) || return 1
    sleep 0.2
  done
}

# --- a private cluster -------------------------------------------------------------------------
dd if=/dev/urandom of="$run/key/munge.key" bs=1024 count=1 status=none
chmod 400 "$run/key/munge.key"
munged --force --socket="$run/munge.sock" --key-file="$run/key/munge.key" \
  --pid-file="$run/munged.pid" --log-file="$work/log/munged.log" --seed-file="$run/munged.seed" ||
  fail "munged did not start"

read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
node=$(hostname -s)
cpus=$(nproc)
cat >"$work/slurm.conf" <<CONF
ClusterName=oceanglobe-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$run/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
PlugStackConfig=$work/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=600
KillWait=2
InactiveLimit=0
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=og Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
: >"$work/plugstack.conf"
export SLURM_CONF=$work/slurm.conf
say "starting slurmctld (port $ctld_port) and slurmd (port $slurmd_port) on $node, $cpus CPUs"
slurmctld -i || fail "slurmctld did not start"
slurmd -N "$node" || fail "slurmd did not start"
node_idle() { sinfo -h -n "$node" -o %T 2>/dev/null | grep -q '^idle'; }
wait_for 30 node_idle || fail "the node did not come up: $(sinfo 2>&1)"

# --- the reference: one process ------------------------------------------------------------------
# 2 s at 8 fps = 17 frames of 96x54: three chunks of 6 (the last one 5).
path=$work/short.toml
cat >"$path" <<TOML
[scene]
sun_elevation_deg = 12
sun_azimuth_deg = 100
width = 96
height = 54
[[keyframe]]
latitude_deg = 37.8
longitude_deg = -14.5
height_m = 3e5
heading_deg = 70
pitch_deg = -50
[[keyframe]]
latitude_deg = 38.0
longitude_deg = -13.0
height_m = 2000
pitch_deg = -8
time_s = 2
TOML
export FPS=8 CHUNK=6 OCEANGLOBE=$og
frames=$("$og" record "$path" --fps "$FPS" --count-frames)
[[ $frames == 17 ]] || fail "expected 17 frames, --count-frames says $frames"
tasks=$(((frames + CHUNK - 1) / CHUNK))
say "reference render: $frames frames"
"$og" -q record "$path" --fps "$FPS" -o "$work/ref/frame_%05d.png"

same_frames() {  # DIR FIRST END: frames FIRST..END-1 in DIR equal the reference
  local i f
  for ((i = $2; i < $3; ++i)); do
    f=$(printf 'frame_%05d.png' "$i")
    [[ -f $1/$f ]] || fail "$1/$f is missing"
    cmp -s "$1/$f" "$work/ref/$f" || fail "$1/$f differs from the single-process render"
  done
}
job_states() { scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sort | uniq -c | tr -s ' ' | xargs; }
finished() { ! squeue -h -j "$1" -o %i 2>/dev/null | grep -q .; }

# --- the array and the encode job, as docs/recording.md submits them ---------------------------
say "submitting an array of $tasks tasks and the encode job"
array=$(sbatch --parsable --array=0-$((tasks - 1)) --cpus-per-task=1 --chdir="$work" \
  --output="$work/log/task-%A_%a.out" "$src/scripts/slurm_record.sh" "$path" "$work/frames")
encode=$(sbatch --parsable --dependency=afterok:"$array" --cpus-per-task=1 --chdir="$work" \
  --output="$work/log/encode-%j.out" "$src/scripts/slurm_record.sh" --encode "$work/frames" "$work/flight.mp4")
wait_for 300 finished "$array,$encode" || fail "the jobs did not finish in 300 s: $(squeue 2>&1)"
[[ $(job_states "$array") == "$tasks JobState=COMPLETED" ]] || fail "array tasks: $(job_states "$array")"
[[ $(job_states "$encode") == "1 JobState=COMPLETED" ]] || fail "encode job: $(job_states "$encode")"
same_frames "$work/frames" 0 "$frames"
[[ $(find "$work/frames" -type f | wc -l) == "$frames" ]] || fail "stray files in $work/frames: $(ls -A "$work/frames")"
if command -v ffprobe >/dev/null; then
  count=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
    -of csv=p=0 "$work/flight.mp4")
  [[ $count == "$frames" ]] || fail "flight.mp4 has $count frames, expected $frames"
fi
say "array: $tasks tasks COMPLETED, $frames frames equal the reference; encode COMPLETED ($work/flight.mp4)"

# --- a task killed part-way, resubmitted with --resume ----------------------------------------
# Task 1 renders frames 6..11. Its renderer is frozen (SIGSTOP) as soon as it starts and let run
# in steps of 10 ms until its first frame is out, so on any machine, however fast, it is killed
# (SIGKILL, as a node failure would) part-way; the task fails.
first=$CHUNK
end=$((2 * CHUNK))
written() { find "$work/resumed" -name 'frame_*.png' | wc -l; }
victim=$(sbatch --parsable --array=1 --cpus-per-task=1 --chdir="$work" \
  --output="$work/log/victim-%A_%a.out" "$src/scripts/slurm_record.sh" "$path" "$work/resumed")
renderer=
deadline=$((SECONDS + 120))
until renderer=$(pgrep -f "$work/resumed/frame_"); do
  ((SECONDS < deadline)) || fail "task 1's renderer did not start in 120 s"
  sleep 0.02
done
kill -STOP $renderer
deadline=$((SECONDS + 300))
until (($(written) >= 1)); do
  ((SECONDS < deadline)) || fail "task 1 wrote no frame in 300 s"
  kill -CONT $renderer || fail "task 1's renderer ended before its first frame"
  sleep 0.01
  kill -STOP $renderer || fail "task 1's renderer ended before it was killed"
done
kill -KILL $renderer  # (scancel sends SIGCONT first: the kill goes to the process itself)
scancel --full --signal=KILL "$victim" 2>/dev/null || true
wait_for 30 finished "$victim" || fail "the killed task did not end"
kept=$(written)
say "task 1 killed after $kept of $CHUNK frames ($(job_states "$victim"))"
((kept < CHUNK)) || fail "task 1 finished before it was stopped"
same_frames "$work/resumed" "$first" "$((first + kept))"  # what it wrote is complete and right
declare -A stamp
for f in "$work"/resumed/frame_*.png; do stamp[$f]=$(stat -c '%i %Y.%y' "$f"); done

resubmitted=$(sbatch --parsable --array=1 --cpus-per-task=1 --chdir="$work" \
  --output="$work/log/resubmitted-%A_%a.out" "$src/scripts/slurm_record.sh" "$path" "$work/resumed")
wait_for 120 finished "$resubmitted" || fail "the resubmitted task did not finish in 120 s"
[[ $(job_states "$resubmitted") == "1 JobState=COMPLETED" ]] || fail "resubmitted: $(job_states "$resubmitted")"
same_frames "$work/resumed" "$first" "$end"
for f in "${!stamp[@]}"; do
  [[ $(stat -c '%i %Y.%y' "$f") == "${stamp[$f]}" ]] || fail "$f was rendered again: --resume must keep it"
done
[[ $(written) == "$CHUNK" ]] || fail "task 1 should hold exactly frames $first..$((end - 1))"
say "resubmitted task 1 COMPLETED: kept $kept frames, rendered $((CHUNK - kept)), all equal the reference"
echo "PASSED"
