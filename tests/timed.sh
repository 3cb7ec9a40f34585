#!/usr/bin/env bash
# Run `MAKE part` for each part, stop at the first failure, and print the
# time each part took (and the total) at the end either way.
make_cmd=$1; shift
declare -a names times
status=0
start_all=$(date +%s)
for part in "$@"; do
  start=$(date +%s)
  $make_cmd --no-print-directory "$part" || status=$?
  names+=("$part"); times+=($(( $(date +%s) - start )))
  [ "$status" -ne 0 ] && break
done
echo
echo "== where the time went =="
for i in "${!names[@]}"; do printf '  %-10s %5d s\n' "${names[$i]}" "${times[$i]}"; done
printf '  %-10s %5d s\n' total $(( $(date +%s) - start_all ))
[ "$status" -ne 0 ] && echo "  (stopped: $part failed)"
exit $status
