# A Slurm cluster of one machine, started by hand (no systemd), for the grader's Slurm tests:
# munged, slurmctld and slurmd with their keys, sockets, state and logs in one folder, on ports
# of their own. Source it; then `slurm_start DIR` and, before leaving, `slurm_stop` (it stops
# exactly the daemons it started, by the pids they wrote). Needs root, and Debian 12's
# slurm-wlm and munge (scripts/install-deps.sh installs them).
# The slurm.conf settings a course's cluster needs are the ones docs/grading.md names:
# DefMemPerCPU (a job without --mem would take the whole node), OverMemoryKill (memory limits
# are not enforced without it or cgroups), MaxArraySize ($SLURM_MAX_ARRAY_SIZE, default 1001:
# a test sets it small to split a class into several arrays).

slurm_pids=()

# slurm_wait_for WHAT SECONDS COMMAND...: runs COMMAND every half second until it succeeds.
slurm_wait_for() {
  local what=$1 tries=$(($2 * 2))
  shift 2
  for _ in $(seq "$tries"); do "$@" > /dev/null 2>&1 && return 0; sleep 0.5; done
  echo "FAIL: $what did not come up in time"
  return 1
}

slurm_start() {
  local dir=$1 host cpus memory port
  for tool in munged slurmctld slurmd sbatch squeue scontrol; do
    command -v $tool > /dev/null ||
      { echo "FAIL: $tool is missing: scripts/install-deps.sh installs slurm-wlm and munge"; return 1; }
  done
  [ "$(id -u)" -eq 0 ] || { echo "FAIL: the Slurm daemons need root"; return 1; }
  mkdir -p "$dir/state" "$dir/spool" && chmod 700 "$dir"
  host=$(hostname -s) cpus=$(nproc)
  memory=$(( $(awk '/MemTotal/ { print int($2 / 1024) }' /proc/meminfo) * 9 / 10 ))
  port=$(( 20000 + RANDOM % 20000 ))  # two ports of its own: another cluster may be running
  head -c 1024 /dev/urandom > "$dir/munge.key" && chmod 400 "$dir/munge.key"
  munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" ||
    { echo "FAIL: munged did not start"; cat "$dir/munged.log"; return 1; }
  slurm_pids+=("$(cat "$dir/munged.pid")")
  cat > "$dir/slurm.conf" <<CONF
ClusterName=rtgrade
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
JobAcctGatherType=jobacct_gather/linux
JobAcctGatherParams=OverMemoryKill
JobAcctGatherFrequency=5
DefMemPerCPU=1024
MaxArraySize=${SLURM_MAX_ARRAY_SIZE:-1001}
ReturnToService=2
SlurmdTimeout=60
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=grading Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -f "$dir/slurm.conf" || { echo "FAIL: slurmctld did not start"; cat "$dir/slurmctld.log"; return 1; }
  slurm_wait_for slurmctld 30 test -s "$dir/slurmctld.pid" || return 1
  slurm_pids+=("$(cat "$dir/slurmctld.pid")")
  slurmd -f "$dir/slurm.conf" || { echo "FAIL: slurmd did not start"; cat "$dir/slurmd.log"; return 1; }
  slurm_wait_for slurmd 30 test -s "$dir/slurmd.pid" || return 1
  slurm_pids+=("$(cat "$dir/slurmd.pid")")
  slurm_wait_for "the node" 60 bash -c "sinfo -h -o %t | grep -qx idle" ||
    { sinfo; tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log"; return 1; }
}

# Stops the daemons this shell started (slurmd first), by pid, and waits for them to go.
slurm_stop() {
  local i pid
  for ((i = ${#slurm_pids[@]} - 1; i >= 0; i--)); do
    pid=${slurm_pids[$i]}
    kill "$pid" 2> /dev/null || continue
    for _ in $(seq 40); do kill -0 "$pid" 2> /dev/null || break; sleep 0.25; done
    kill -KILL "$pid" 2> /dev/null || true
  done
  slurm_pids=()
}

# slurm_wait_done JOB SECONDS: until no task of JOB is pending or running.
slurm_wait_done() {
  local job=$1 tries=$(($2 * 2))
  for _ in $(seq "$tries"); do
    [ -z "$(squeue -h -j "$job" 2> /dev/null)" ] && return 0
    sleep 0.5
  done
  echo "FAIL: job $job did not end within $2 s"
  squeue
  return 1
}
