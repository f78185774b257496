#!/usr/bin/env bash
# A throwaway single-node Slurm cluster on localhost, for the farm tests: munged with a
# generated key, slurmctld and slurmd with a slurm.conf in a temporary folder, no cgroups.
# Source it, then: cluster_start DIR (as root; exports SLURM_CONF, sets CLUSTER_PIDS) and
# cluster_stop (kills exactly the pids it started).

cluster_start() {
    local dir=$1
    mkdir -p "$dir"/{munge,state,spool,log}
    chmod 700 "$dir/munge"
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge/munge.key"
    # munged refuses a world-writable socket folder; ours is private to the cluster.
    munged --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.sock" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
        --seed-file="$dir/munge/munge.seed" --force || return 1
    local cpus
    cpus=$(nproc)
    local host
    host=$(hostname -s)
    cat >"$dir/slurm.conf" <<CONF
ClusterName=penumbra-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.sock,cred_expire=10
CredType=cred/munge
SlurmctldPort=$((20000 + RANDOM % 20000))
SlurmdPort=$((40000 + RANDOM % 20000))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
MpiDefault=none
ReturnToService=2
KillWait=30
MinJobAge=600
# Small, so the farm test's job file needs two arrays (submit cuts at MaxArraySize).
MaxArraySize=5
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -i -f "$SLURM_CONF" || return 1
    slurmd -f "$SLURM_CONF" || return 1
    CLUSTER_PIDS=""
    local i
    for i in $(seq 1 100); do
        if [ -s "$dir/slurmctld.pid" ] && [ -s "$dir/slurmd.pid" ] &&
            sinfo -h -o %T 2>/dev/null | grep -q idle; then
            CLUSTER_PIDS="$(cat "$dir/munge/munged.pid") $(cat "$dir/slurmctld.pid") $(cat "$dir/slurmd.pid")"
            return 0
        fi
        sleep 0.2
    done
    echo "slurm_cluster: the node did not come up; logs in $dir/log" >&2
    return 1
}

cluster_stop() {
    local dir=$1 pid f
    for f in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
        [ -s "$f" ] || continue
        pid=$(cat "$f")
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    done
}
