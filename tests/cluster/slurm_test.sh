#!/usr/bin/env bash
# Slurm, for real: starts a one-node Slurm cluster on this machine (munged, slurmctld and slurmd of
# Debian's packages, every file of theirs in a temporary folder, stopped at the end), grades a class
# of 20 with course/cluster/grade.sbatch as a job array of 4 shards, merges the shard gradebooks and
# checks that the merged gradebook is the one-machine gradebook. Also checks that every layer of the
# controllers' sandbox holds inside a Slurm job as outside.
# Needs root (slurmd, and SlurmUser=root) and the packages of tests/cluster/packages.txt:
#   slurmctld slurmd slurm-client munge
# else exits 77 (skipped), saying why.
# Usage: slurm_test.sh FROB SOURCE_DIR GRADE_SBATCH
frob=$1 source=$2 sbatch_script=$3
source "$(dirname "$0")/common.sh"

[ "$(id -u)" = 0 ] || skip "not root: slurmd runs as root here (SlurmUser=root)"
for program in munged mungekey munge slurmctld slurmd sbatch scontrol sinfo scancel; do
  command -v "$program" > /dev/null || skip "no $program: apt-get install --no-install-recommends slurmctld slurmd slurm-client munge (tests/cluster/packages.txt)"
done
make_work

# Stops what the test started: the jobs first (slurmd leaves running jobs behind), then the daemons.
daemons=()
cleanup() {
  if [ -n "${SLURM_CONF:-}" ] && scontrol ping > /dev/null 2>&1; then
    scancel --user=root 2> /dev/null || true  # every job of this cluster, the test's own
    # Each job step has a socket in slurmd's spool until its slurmstepd has ended.
    for _ in $(seq 100); do compgen -G "$work/slurm/spool/localhost_*" > /dev/null || break; sleep 0.1; done
  fi
  local pid
  for pid in "${daemons[@]}"; do kill "$pid" 2> /dev/null || true; done
  for pid in "${daemons[@]}"; do wait "$pid" 2> /dev/null || true; done
}
# on_failure WHAT: the daemons' logs, then fail.
on_failure() {
  local log
  for log in "$work"/logs/*; do echo "--- $log" >&2 && tail -n 30 "$log" >&2; done
  fail "$*"
}
# until_ready WHAT COMMAND...: polls COMMAND until it succeeds, for at most 30 s.
until_ready() {
  local what=$1 i
  shift
  for i in $(seq 300); do "$@" > /dev/null 2>&1 && return 0; sleep 0.1; done
  on_failure "$what is not up after 30 s"
}
# A free TCP port of localhost (nothing answers on it).
free_port() {
  local port
  while :; do
    port=$((20000 + RANDOM % 30000))
    (exec 3<> "/dev/tcp/127.0.0.1/$port") 2> /dev/null || { echo "$port"; return; }
  done
}
mkdir -p "$work/logs" "$work/munge" "$work/slurm/state" "$work/slurm/spool"

# The daemons run in sessions of their own, so that a ^C to the test stops them only through cleanup,
# once their jobs are cancelled.
# munged, with a key and a socket of its own (the socket's folder open to all, as munged demands).
mkdir -m 700 "$work/munge-key"
mungekey --create --keyfile "$work/munge-key/munge.key"
setsid munged --foreground --key-file "$work/munge-key/munge.key" --socket "$work/munge/socket" --pid-file "$work/munge/pid" \
  --seed-file "$work/munge-key/seed" > "$work/logs/munged.log" 2>&1 &
daemons+=($!)
until_ready munged munge --socket "$work/munge/socket" --no-input

# The cluster: this machine, as slurmd -C sees it (but a modest memory), in one partition.
controller_port=$(free_port)
node_port=$(free_port)
[ "$node_port" != "$controller_port" ] || node_port=$((controller_port + 1))
hardware=$(slurmd -C | head -n 1 | sed 's/NodeName=[^ ]*//; s/RealMemory=[^ ]*//')
export SLURM_CONF="$work/slurm/slurm.conf"
cat > "$SLURM_CONF" <<EOF
ClusterName=frobtest
SlurmctldHost=localhost
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/logs/slurmctld.log
SlurmdLogFile=$work/logs/slurmd.log
PlugStackConfig=$work/slurm/plugstack.conf
MailProg=/bin/true
# No cgroups: processes tracked through their parents, tasks not bound.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
# sbatch --wait polls every 2 s if MinJobAge is at most 5 (else after 2, 8, then every 32 s); a job
# stays known MinJobAge seconds after it ends, time enough for the next poll.
MinJobAge=5
NodeName=localhost NodeAddr=127.0.0.1 $hardware RealMemory=1000 State=UNKNOWN
PartitionName=all Nodes=localhost Default=YES MaxTime=30 State=UP
EOF
: > "$work/slurm/plugstack.conf"  # no SPANK plugins (not those of /etc/slurm)
setsid slurmctld -D -f "$SLURM_CONF" > "$work/logs/slurmctld.out" 2>&1 &
daemons+=($!)
until_ready slurmctld scontrol ping
setsid slurmd -D -N localhost -f "$SLURM_CONF" > "$work/logs/slurmd.out" 2>&1 &
daemons+=($!)
node_idle() { [ "$(sinfo --noheader --nodes=localhost --format=%t)" = idle ]; }
until_ready "slurmd (the node idle)" node_idle

make_class "$source"
grade_one_machine
cd "$work"

# submit ARGS...: sbatch --wait, for at most 4 minutes.
submit() {
  local status=0
  interruptible timeout 240 sbatch --parsable --wait --time=5 "$@" > sbatch.out 2> sbatch.err || status=$?
  [ "$status" = 0 ] || { cat sbatch.err slurm-*.log >&2; on_failure "sbatch $* exited $status"; }
}

# The sandbox inside a job: every layer as outside.
world="$source/assignments/go_to_goal/worlds/lounge.toml"
sandbox_layers() { sed -n '/"sandbox": \[/,/^ \]/p' "$1"; }
"$frob" run class/student06/controller.cpp --world "$world" --seconds 1 --json > outside.json 2> outside.err || { cat outside.err >&2; fail "frob run"; }
submit --output=slurm-sandbox.log --wrap "'$frob' run class/student06/controller.cpp --world '$world' --seconds 1 --json"
sandbox_layers outside.json > outside-layers.txt
sandbox_layers slurm-sandbox.log > job-layers.txt
grep -q '"applied": true' outside-layers.txt || { cat outside.json >&2; fail "no sandbox layers in frob run --json"; }
diff -u outside-layers.txt job-layers.txt >&2 || fail "the sandbox inside a Slurm job differs from outside (diff above)"

# The class as a job array of 4 shards, a CPU each (on 2 CPUs, two at a time).
mkdir shards
start=$SECONDS
export FROB="$frob"
submit --array=1-4 --cpus-per-task=1 --output=slurm-grade-%a.log "$sbatch_script" \
  go_to_goal class/ shards/grades --visible-only --secret secret.txt
for i in 1 2 3 4; do grep -q "class/student" "slurm-grade-$i.log" || { cat "slurm-grade-$i.log" >&2; fail "task $i graded nothing"; }; done
check_shards shards/grades 4
echo "a one-node Slurm cluster graded the class in 4 shards in $((SECONDS - start)) s; merged, the gradebook is the one-machine gradebook"
