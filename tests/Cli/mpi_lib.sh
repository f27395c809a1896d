# What tests/Cli/mpi.sh and mpi_compare.sh share, sourced by both once they have set `app`: mpirun's environment on
# this machine, a work folder removed on the way out (with a job a failed check left running), the skip where
# there is no MPI, and the checks of how a job ends. Each script defines left_behind: whether a failed job left an
# output in $work.
command -v mpirun >/dev/null || { echo "no mpirun: skipped"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 # CI runs as root
export OMPI_MCA_rmaps_base_oversubscribe=1 # more ranks than this machine's 2 cores
# Containers often forbid the cross-memory attach (ptrace) Open MPI's shared-memory transport tries first.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
work=$(mktemp -d)
pid=
# On the way out, the job of a failed check and its ranks (they name $work in their flags).
trap '[ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; pkill -KILL -f -- "$work" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; [ -f "$work/stderr" ] && grep -v "^\[" "$work/stderr" | tail -20; exit 1; }
mpi() { mpirun -q "$@"; }
# A build without MPI refuses to be started as several copies: skip then.
if mpi -np 2 "$app" --headless --quiet --scene cornell-box-lights --width 4 --spp 1 2>&1 | grep -q "built without MPI"; then
    echo "built without MPI: skipped"; exit 77
fi

# expect_one_error STATUS PATTERN: the job failed, with one "error:" line matching PATTERN and no output left.
expect_one_error() {
    [ "$1" != 0 ] || fail "exit status 0 where the job should fail"
    [ "$(grep -c '^error:' "$work/stderr")" = 1 ] || fail "one error line expected"
    grep '^error:' "$work/stderr" | grep -Eq "$2" || fail "the error line does not match '$2'"
    ! left_behind || fail "a failed job left outputs behind: $(ls "$work")"
}
rank_pid() { # RANK ARGS: the process mpirun started as rank RANK, of the app run with ARGS first
    local p
    for p in $(pgrep -f "$(basename "$app") $2"); do
        tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1" && echo "$p"
    done
}
wait_bounded() { # SECONDS: wait for the job $pid; its status in $status, or fail past the bound
    local start=$EPOCHREALTIME
    for _ in $(seq $(( $1 * 20 ))); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.05
    done
    kill -0 "$pid" 2>/dev/null && fail "the job still runs $1 s later"
    wait "$pid"
    status=$?
    pid=
    echo "    ended in $(python3 -c "print(f'{$EPOCHREALTIME - $start:.2f}')") s"
}
