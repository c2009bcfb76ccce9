# Sourced by scripts that start a program and wait for a line it prints.

# wait_for_output FILE SED_SCRIPT PID [TENTHS]: the first line `sed -n SED_SCRIPT FILE` prints,
# waited for up to TENTHS tenths of a second (100) while process PID lives; empty when none came.
wait_for_output() {
    local found="" _
    for _ in $(seq 1 "${4:-100}"); do
        found=$(sed -n "$2" "$1" 2> /dev/null | head -n 1)
        [[ -n "$found" ]] && break
        kill -0 "$3" 2> /dev/null || break
        sleep 0.1
    done
    echo "$found"
}
