#!/usr/bin/env bash
# The hostile-user cases of issue 22, one line each: case, exit code, seconds, peak memory, and
# the first line of what mcdyna said. Run it with any mcdyna binary to compare builds:
#   tools/verify/fault_campaign.sh [BINARY] [WORKDIR]
# Exit codes: 124/137 = killed by the timeout (a hang), 134 = abort, 139 = SIGSEGV.
# The full-disk cases mount small tmpfs file systems and need root; without it they say so.
set -u
bin=$(realpath "${1:-build/mcdyna}")
src=$(cd "$(dirname "$0")/../.." && pwd)
work=${2:-$(mktemp -d)}
mkdir -p "$work"
cd "$work" || exit 1
py=/usr/bin/python3

# case NAME TIMEOUT COMMAND...: runs COMMAND with a timeout (SIGTERM, then SIGKILL 5 s later).
case_() {
  local name=$1 limit=$2
  shift 2
  local start end rc mem first
  start=$(date +%s.%N)
  /usr/bin/time -f "%M" -o "$name.mem" timeout -k 5 "$limit" "$@" >"$name.out" 2>&1
  rc=$?
  end=$(date +%s.%N)
  mem=$(tail -1 "$name.mem" 2>/dev/null)
  [[ "$mem" =~ ^[0-9]+$ ]] || mem=0
  # /usr/bin/time reports a signal death as its own exit code; keep the shell's view.
  first=$(grep -a -v '^\s*$' "$name.out" | grep -a -m1 -iE 'error|warning|terminat|usage|internal|Segmentation|abort|ready|mcdyna' | cut -c1-110)
  printf '%-28s %4s %7.1f s %7d MB  %s\n' "$name" "$rc" "$(echo "$end - $start" | bc)" \
    $((mem / 1024)) "$first"
}

cube=$src/decks/cube/cube_drop.k
$py - "$cube" <<'EOF'
import sys
cube = open(sys.argv[1]).read()
def w(name, text): open(name, 'w').write(text)
w('chain.k', '*KEYWORD\n*PARAMETER_EXPRESSION\n' +
  ''.join(f'R Q{i},Q{i-1}+1\n' for i in range(10000, 0, -1)) + 'R Q0,1\n*END\n')
for name, op in [('pow', '1**'), ('minus', '-'), ('plus', '+')]:
    w(f'{name}.k', '*KEYWORD\n*PARAMETER_EXPRESSION\nR X,' + op * 300000 + '1\n*END\n')
step = '       0.0       0.9\n'
w('dt2ms_1e6.k', cube.replace(step, '       0.0       0.9       0.0       0.0     1.0E6\n'))
w('dt2ms_1e30.k', cube.replace(step, '       0.0       0.9       0.0       0.0    1.0E30\n'))
w('out_1e-15.k', cube.replace('*DATABASE_BINARY_D3PLOT\n    1.0E-6', '*DATABASE_BINARY_D3PLOT\n   1.0E-15'))
w('many_states.k', cube.replace('*DATABASE_BINARY_D3PLOT\n    1.0E-6', '*DATABASE_BINARY_D3PLOT\n    1.0E-7')
  .replace('*DATABASE_GLSTAT\n    1.0E-7', '*DATABASE_GLSTAT\n    1.0E-9'))
w('dump.k', cube.replace('*END', '*DATABASE_BINARY_D3DUMP\n       200\n*END'))
w('empty.k', '')
nodes = cube[cube.index('*NODE'):cube.index('*ELEMENT_SOLID')]
w('nodes_only.k', '*KEYWORD\n*CONTROL_TERMINATION\n1.0E-5\n' + nodes + '*END\n')
w('field_70k.k', '*KEYWORD\n*NODE\n1,0.0,' + '7' * 70000 + 'x,0.0\n*END\n')
w('a.csv', 'time,force\n0,0\n1,1\n2,4\n')
w('nul.csv', 'time,fo\0rce\n0,0\n1,1\n')
w('bom.csv', '\ufefftime,force\n0,0\n1,1\n')
w('dup.csv', 'time,force,force\n0,0,1\n1,1,2\n')
with open('big.csv', 'w') as f:  # about 200 MB
    f.write('time,a,b,c,d\n')
    row = ',{0:.9e},{0:.9e},{0:.9e},{0:.9e}\n'
    for i in range(2_900_000):
        f.write(f'{i:.9e}' + row.format(i * 0.5))
EOF

echo "mcdyna fault campaign: $bin"
echo "case                           rc   time      peak     first line"
# 1. Reader recursion.
case_ param_chain_reverse 60 "$bin" check -q chain.k
case_ expr_300k_power 60 "$bin" check -q pow.k
case_ expr_300k_minus 60 "$bin" check -q minus.k
case_ expr_300k_plus 60 "$bin" check -q plus.k
# 2. Output schedule.
case_ dt2ms_1e6 20 "$bin" run dt2ms_1e6.k --out o_dt2ms_1e6 -q
case_ dt2ms_1e30 20 "$bin" run dt2ms_1e30.k --out o_dt2ms_1e30 -q
case_ d3plot_dt_1e-15 60 "$bin" run out_1e-15.k --out o_out -q
# 3. Full disk (tmpfs of a few sizes).
for size in 1m 200k 64k; do
  mkdir -p "disk_$size"
  if mount -t tmpfs -o "size=$size" tmpfs "disk_$size" 2>/dev/null; then
    case_ "disk_full_$size" 60 "$bin" run many_states.k --out "disk_$size/out" -q
    umount "disk_$size"
  else
    echo "disk_full_$size: no tmpfs here (needs root)"
  fi
done
# 4. Restart dumps: 98 corruptions of one dump, and a FIFO.
"$bin" run dump.k --out o_dump -q >/dev/null 2>&1
if [ -f o_dump/d3dump01 ]; then
  $py - o_dump/d3dump01 <<'EOF'
import random, sys
data = open(sys.argv[1], 'rb').read()
rng = random.Random(22)
for k in range(98):
    b = bytearray(data)
    for _ in range(1 + k % 4):
        i = rng.randrange(64, len(b))
        b[i] ^= 1 << rng.randrange(8)
    open(f'corrupt_{k:02d}', 'wb').write(b)
EOF
  declare -A tally=()
  for k in $(seq -w 0 97); do
    rm -rf o_corrupt && cp -r o_dump o_corrupt  # the restart continues the run's histories
    timeout -k 5 60 "$bin" run dump.k --out o_corrupt -q --restart "corrupt_$k" >"corrupt_$k.out" 2>&1
    rc=$?
    tally[$rc]=$((${tally[$rc]:-0} + 1))
  done
  printf '%-28s %s\n' "restart_flipped_x98" "$(for rc in "${!tally[@]}"; do printf 'exit %s: %s  ' "$rc" "${tally[$rc]}"; done)"
fi
rm -f fifo && mkfifo fifo
rm -rf o_fifo && cp -r o_dump o_fifo
case_ restart_fifo 10 "$bin" run dump.k --out o_fifo -q --restart fifo
# 5. Exit codes and small things.
touch a_file
ln -sf /nonexistent/dir dangling
case_ out_is_a_file 20 "$bin" run "$cube" --out a_file -q
case_ out_dev_null 20 "$bin" run "$cube" --out /dev/null -q
case_ out_dangling_link 20 "$bin" run "$cube" --out dangling -q
case_ out_in_proc 20 "$bin" run "$cube" --out /proc/mcdyna_out -q
case_ out_name_too_long 20 "$bin" run "$cube" --out "$(printf 'x%.0s' $(seq 300))" -q
case_ compare_dev_zero 40 "$bin" compare /dev/zero a.csv
case_ compare_dev_urandom 40 "$bin" compare /dev/urandom a.csv
case_ compare_points_4e9 20 "$bin" compare a.csv a.csv --points 4000000000
case_ compare_200MB_itself 120 "$bin" compare big.csv big.csv
case_ compare_nul_byte 20 "$bin" compare nul.csv a.csv
case_ compare_bom 20 "$bin" compare bom.csv a.csv -c force
case_ compare_duplicate_names 20 "$bin" compare dup.csv a.csv
case_ compare_tol_nan 20 "$bin" compare a.csv a.csv --tol nan
case_ compare_from_nan 20 "$bin" compare a.csv a.csv --from nan
case_ compare_directory 20 "$bin" compare . a.csv
case_ check_empty_deck 20 "$bin" check -q empty.k
case_ run_empty_deck 20 "$bin" run empty.k --out o_empty -q
case_ run_missing_deck 20 "$bin" run missing.k --out o_missing -q
case_ run_nodes_only 20 "$bin" run nodes_only.k --out o_nodes -q
case_ check_field_70k 20 "$bin" check -q field_70k.k
printf '%-28s      %d bytes of messages\n' "  (field_70k output size)" "$(wc -c <check_field_70k.out)"
case_ help 20 "$bin" --help
printf '%-28s      %s\n' "  (help usage line)" "$(grep -m1 -i usage help.out)"
