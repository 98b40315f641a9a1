#!/usr/bin/env bash
# glossy on a real Slurm (CTest label "cluster", left out of the default suite): starts a single-node
# cluster from Debian's packages — munged, slurmctld and slurmd, on a generated slurm.conf with free ports
# on localhost, all state in the work folder — and checks, through scripts/cluster/submit:
#   1. sheets: a 4-task array over 4 materials plus its merge job; every sheet and the merged tables, and the
#      tables equal those of a single-machine `glossy sheets` of the same materials and settings;
#   2. fits: the same for a 4-task `glossy fit --measured-dir` array and the merge into parameter files;
#   3. resume: one task of an array cancelled mid-run (scancel), then the array resubmitted: the cancelled
#      task's sheet is made, the finished ones are skipped, not rendered again;
#   4. study: a tiny `glossy study` (2 materials × 2 lightings) as a 3-task array plus its merge job, which
#      analyses; the analysis equals, byte for byte, that of the same study run whole on one machine.
# Stops its daemons and removes its folder however it ends. Needs root (Slurm's daemons run as root here);
# exits 77 (skip), saying why, without root or without the packages (scripts/setup-cluster installs them).
# Usage: slurm_test.sh --exe GLOSSY --source-dir DIR --shared-dir DIR --work DIR
set -euo pipefail

while [ $# -gt 0 ]; do
  case "$1" in
    --exe) exe=$2 ;;
    --source-dir) source_dir=$2 ;;
    --shared-dir) shared_dir=$2 ;;
    --work) work=$2 ;;
    *) echo "slurm_test: unknown argument $1" >&2; exit 2 ;;
  esac
  shift 2
done
skip() { echo "Cluster.Slurm: skipped: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "needs root to run Slurm's daemons"
for tool in munged slurmctld slurmd sbatch squeue scancel scontrol; do
  command -v "$tool" >/dev/null || skip "$tool is missing (scripts/setup-cluster installs slurmctld, slurmd, slurm-client, munge)"
done
materials=(alum-bronze blue-rubber chrome gold-paint)
for m in "${materials[@]}"; do
  [ -f "$shared_dir/merl/$m.binary.xz" ] || skip "$shared_dir/merl/$m.binary.xz is absent"
done

rm -rf "$work"
mkdir -p "$work"/{munge,state,spool,log}
work=$(cd "$work" && pwd)
export SLURM_CONF=$work/slurm.conf GLOSSY=$exe
stop() {
  scancel --full --quiet --user=root 2>/dev/null || true
  scontrol shutdown >/dev/null 2>&1 || true
  for pid_file in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [ -f "$pid_file" ] || continue
    pid=$(cat "$pid_file")
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  munged --stop --socket="$work/munge/munge.sock" >/dev/null 2>&1 || true
}
failed() {
  echo "Cluster.Slurm: FAILED: $*" >&2
  for f in "$work"/log/*.log "$work"/run/*.log; do [ -f "$f" ] && { echo "--- $f" >&2; tail -n 20 "$f" >&2; }; done
  exit 1
}
trap 'stop; rm -rf "$work"' EXIT

# munge, with a key and socket of its own.
chmod 700 "$work/munge"
head -c 1024 /dev/urandom >"$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.sock" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/log/munged.log" --seed-file="$work/munge/munged.seed" || failed "munged did not start"

# Two free ports on localhost, and the cluster: this machine as its only node.
read -r ctld_port slurmd_port < <(python3 -c 'import socket
s = [socket.socket() for _ in range(2)]
[x.bind(("127.0.0.1", 0)) for x in s]
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
cpus=$(nproc)
cat >"$SLURM_CONF" <<EOF
ClusterName=glossytest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=glossy Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -f "$SLURM_CONF" || failed "slurmctld did not start"
slurmd -f "$SLURM_CONF" || failed "slurmd did not start"
for _ in $(seq 100); do sinfo -h -o %t 2>/dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %t | grep -q idle || failed "the node did not come up"
echo "Cluster.Slurm: single-node Slurm up ($host, $cpus CPUs, ports $ctld_port/$slurmd_port)"

# Waits for jobs to leave the queue (at most $2 seconds).
wait_jobs() {
  local start=$SECONDS
  while [ -n "$(squeue -h -j "$1" 2>/dev/null)" ]; do
    [ $((SECONDS - start)) -lt "$2" ] || failed "jobs $1 still queued after $2 s: $(squeue -j "$1")"
    sleep 0.5
  done
}
state() { sacct_state=$(scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1); echo "$sacct_state"; }

mkdir -p "$work/lib" "$work/tables" "$work/run"
for m in "${materials[@]}"; do
  cp "$source_dir/materials/library/merl/$m.toml" "$work/lib/"
  ln -s "$shared_dir/merl/$m.binary.xz" "$work/tables/$m.binary.xz"
done
cd "$work/run"
export GLOSSY_SBATCH_OPTIONS="--cpus-per-task=1"
sheet_options=(--merl-dir "$shared_dir/merl" --width 32 --height 32 --spp 8 --seed 7 --threads 1)
fit_options=(--model cook-torrance --metric E2 --starts 1 --max-iterations 10 --threads 1)

# 1. Sheets: the array and its merge.
t0=$SECONDS
jobs=$("$source_dir/scripts/cluster/submit" sheets 4 "$work/sheets" "$work/lib" "${sheet_options[@]}")
array=$(echo "$jobs" | awk '$1 == "array" {print $2}') merge=$(echo "$jobs" | awk '$1 == "merge" {print $2}')
wait_jobs "$array,$merge" 300
for m in "${materials[@]}"; do
  [ -s "$work/sheets/$m.exr" ] && [ -s "$work/sheets/$m.png" ] || failed "no sheet of $m"
done
for k in 0 1 2 3; do
  grep -q "shard $k/4 from Slurm array task $k (array 0-3, 4 tasks): 1 of 4 materials" glossy-sheets-"${array}_$k".log ||
    failed "task $k did not take its shard from Slurm: $(cat glossy-sheets-"${array}_$k".log)"
done
[ "$(state "$merge")" = COMPLETED ] || failed "the merge job is $(state "$merge")"
# A row per panel and one for the noise floor (merge_command.cpp).
[ "$(wc -l <"$work/sheets/errors.csv")" -eq $((1 + 4 * 8)) ] || failed "errors.csv has not 4 sheets × (7 panels + the noise floor)"
echo "Cluster.Slurm: sheets: 4 tasks and the merge in $((SECONDS - t0)) s"
# The same materials on one machine: the same figures.
"$exe" sheets "$work/lib" -o "$work/single-sheets" "${sheet_options[@]}" 2>"$work/run/single-sheets.log" >/dev/null
"$exe" merge sheets "$work/single-sheets" --csv "$work/single-sheets/errors.csv" --json "$work/single-sheets/errors.json" 2>/dev/null
cmp -s "$work/sheets/errors.csv" "$work/single-sheets/errors.csv" || failed "the merged sheet figures differ from one machine's:
$(diff "$work/sheets/errors.csv" "$work/single-sheets/errors.csv" | head)"
cmp -s "$work/sheets/errors.json" "$work/single-sheets/errors.json" || failed "errors.json differs from one machine's"

# 2. Fits: the array and the merge into parameter files.
t0=$SECONDS
jobs=$("$source_dir/scripts/cluster/submit" fits 4 "$work/tables" "$work/fits" "$work/fitted-lib" "${fit_options[@]}")
array=$(echo "$jobs" | awk '$1 == "array" {print $2}') merge=$(echo "$jobs" | awk '$1 == "merge" {print $2}')
wait_jobs "$array,$merge" 300
[ "$(state "$merge")" = COMPLETED ] || failed "the fits' merge job is $(state "$merge")"
"$exe" fit --measured-dir "$work/tables" --out-dir "$work/single-fits" "${fit_options[@]}" 2>/dev/null
"$exe" merge fits "$work/single-fits" -o "$work/single-lib" 2>/dev/null
for m in "${materials[@]}"; do
  [ -s "$work/fitted-lib/$m.toml" ] || failed "no merged parameter file of $m"
  grep -q 'model = "cook-torrance"' "$work/fitted-lib/$m.toml" || failed "$m.toml holds no cook-torrance fit"
  cmp -s "$work/fitted-lib/$m.toml" "$work/single-lib/$m.toml" || failed "$m's fit differs from one machine's"
done
echo "Cluster.Slurm: fits: 4 tasks and the merge in $((SECONDS - t0)) s"

# 3. A task cancelled mid-run, then the array resubmitted.
t0=$SECONDS
slow=(--merl-dir "$shared_dir/merl" --width 64 --height 64 --spp 1024 --seed 7 --threads 1)
jobs=$("$source_dir/scripts/cluster/submit" sheets 4 "$work/resume" "$work/lib" "${slow[@]}")
array=$(echo "$jobs" | awk '$1 == "array" {print $2}') merge=$(echo "$jobs" | awk '$1 == "merge" {print $2}')
for _ in $(seq 600); do [ "$(squeue -h -j "${array}_2" -o %t 2>/dev/null)" = R ] && break; sleep 0.1; done
sleep 1
[ "$(squeue -h -j "${array}_2" -o %t)" = R ] || failed "task 2 never ran"
scancel "${array}_2"
victim=${materials[2]}
wait_jobs "$array" 600
# afterok can no longer hold: the merge job cancels itself (--kill-on-invalid-dep).
wait_jobs "$merge" 60
[ "$(state "$merge")" = CANCELLED ] || failed "the merge job of the cancelled array is $(state "$merge")"
[ ! -e "$work/resume/$victim.exr" ] || failed "the cancelled task's sheet exists"
declare -A before
for m in "${materials[@]}"; do
  [ "$m" = "$victim" ] && continue
  [ -s "$work/resume/$m.exr" ] || failed "task of $m did not finish"
  before[$m]=$(stat -c %Y.%s "$work/resume/$m.exr")
done
jobs=$("$source_dir/scripts/cluster/submit" sheets 4 "$work/resume" "$work/lib" "${slow[@]}")
array=$(echo "$jobs" | awk '$1 == "array" {print $2}') merge=$(echo "$jobs" | awk '$1 == "merge" {print $2}')
wait_jobs "$array,$merge" 600
[ "$(state "$merge")" = COMPLETED ] || failed "the resubmitted merge job is $(state "$merge")"
[ -s "$work/resume/$victim.exr" ] || failed "the resubmission did not make $victim's sheet"
grep -q "$victim: complete, skipped" glossy-sheets-"${array}"_2.log && failed "the cancelled sheet was taken as complete"
for k in 0 1 3; do
  m=${materials[$k]}
  grep -q "$m: complete, skipped" glossy-sheets-"${array}_$k".log || failed "task $k rendered $m again: $(cat glossy-sheets-"${array}_$k".log)"
  [ "$(stat -c %Y.%s "$work/resume/$m.exr")" = "${before[$m]}" ] || failed "$m's sheet was written again"
done
[ "$(wc -l <"$work/resume/errors.csv")" -eq $((1 + 4 * 8)) ] || failed "the resumed errors.csv has not 4 sheets × (7 panels + the noise floor)"
echo "Cluster.Slurm: resume: task 2 cancelled mid-run, resubmitted: 1 sheet made, 3 skipped, in $((SECONDS - t0)) s"
# 4. A study: the array renders its sheets, the merge job analyses them.
t0=$SECONDS
cat >"$work/tiny-study.toml" <<TOML
materials = ["merl/gold-paint", "merl/chrome"]
[lightings]
sky = { sky = true }
grey = { constant = 0.8 }
[settings]
width = 16
height = 16
spp = 16
seed = 7
panels = "measured,microfacet:E2,smooth:E2,cook-torrance:E2"
[analysis]
resamples = 200
TOML
study_options=(--merl-dir "$shared_dir/merl")
jobs=$("$source_dir/scripts/cluster/submit" study 3 "$work/tiny-study.toml" "$work/study" "${study_options[@]}")
array=$(echo "$jobs" | awk '$1 == "array" {print $2}') merge=$(echo "$jobs" | awk '$1 == "merge" {print $2}')
wait_jobs "$array,$merge" 300
[ "$(state "$merge")" = COMPLETED ] || failed "the study's merge job is $(state "$merge")"
for k in 0 1 2; do
  grep -q "shard $k/3 from Slurm array task $k (array 0-2, 3 tasks)" glossy-study-"${array}_$k".log ||
    failed "study task $k did not take its shard from Slurm: $(cat glossy-study-"${array}_$k".log)"
done
[ -n "$(ls -A "$work/study/analysis" 2>/dev/null)" ] || failed "the merge job wrote no analysis"
"$exe" study "$work/tiny-study.toml" -o "$work/single-study" --threads 1 "${study_options[@]}" >/dev/null 2>"$work/run/single-study.log" ||
  failed "the single-machine study failed: $(tail -n 3 "$work/run/single-study.log")"
diff -r "$work/study/analysis" "$work/single-study/analysis" >/dev/null || failed "the array's study analysis differs from one machine's:
$(diff -r "$work/study/analysis" "$work/single-study/analysis" | head)"
cmp -s "$work/study/study.json" "$work/single-study/study.json" || failed "study.json differs from one machine's"
echo "Cluster.Slurm: study: 3 tasks and the analysing merge in $((SECONDS - t0)) s"
echo "Cluster.Slurm: passed"
