#!/usr/bin/env bash
# tests/timed.sh MAKE SETUP... -- PART...: run `MAKE part` for each set-up
# part, then each test part; stop at the first failure, and print the time
# each part took at the end either way: the set-up (installing the .venv on
# a fresh clone) and the tests each with their subtotal.
make_cmd=$1; shift
declare -a names times kinds
status=0
kind=setup
start_all=$(date +%s)
for part in "$@"; do
  if [ "$part" = "--" ]; then kind=tests; continue; fi
  start=$(date +%s)
  $make_cmd --no-print-directory "$part" || status=$?
  names+=("$part"); times+=($(( $(date +%s) - start ))); kinds+=("$kind")
  [ "$status" -ne 0 ] && break
done
echo
echo "== where the time went =="
for group in setup tests; do
  sum=0
  for i in "${!names[@]}"; do
    [ "${kinds[$i]}" = "$group" ] || continue
    printf '  %-12s %5d s\n' "${names[$i]}" "${times[$i]}"
    sum=$(( sum + times[i] ))
  done
  printf '  %-12s %5d s\n' "($group)" "$sum"
done
printf '  %-12s %5d s\n' total $(( $(date +%s) - start_all ))
[ "$status" -ne 0 ] && echo "  (stopped: $part failed)"
exit $status
