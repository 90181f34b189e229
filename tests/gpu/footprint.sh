#!/usr/bin/env bash
# tests/gpu/footprint.sh - the GPU footprint of each model family (needs nvcc;
# no GPU: it reads what ptxas and the PTX say). For each FAMILY_<NAME> kernel
# of tests/gpu/kernels.cu: registers, stack frame (local memory), spills,
# global data (the tables) and user __constant__ memory (cmem[3]), and the
# number of f64 instructions in the PTX. Fails when
#   - any family uses user __constant__ memory (the tables live in global
#     memory, emitted only where used),
#   - a family without tables has global data,
#   - any PTX has an f64 instruction (every model computes in float),
#   - a BSDF / phase sampler spills or has a stack frame.
# Usage: tests/gpu/footprint.sh [OUT_DIR] (default build/gpu)
set -u
out=${1:-build/gpu}
mkdir -p "$out"
# family:uses-tables:may-use-stack (the random walk and the tracker loop keep state; GENERIC:
# appear_bsdf over Lambert, conductor and dielectric with the other parts compiled out, which
# must have no stack; GENERIC_ALL: the same kernel with every part, the random walks included;
# MATERIALS: the named metals' and glasses' lookups and the dispersive dielectric, whose loop over
# the secondary wavelengths indexes its spectra at run time: 120 bytes of stack, measured;
# OPENPBR: every lobe and the thin film in one kernel, its calls not inlined, the model read from
# global memory: 392 bytes of stack and 165 registers, measured (400 and 158 before the thirteenth
# session's plain path, inlined at three calls; 224 bytes and 171 registers before
# the eleventh session, whose calls take the 43-float state at wo by pointer, where they returned
# it by value; the kernel took the then 1004-byte model by value until 2026-12-05 and counted its
# copy: 1232 bytes then), to reduce)
families="LAMBERT:0:0 EON:0:0 SHEEN:1:0 HG:0:0 WARD:0:0 CONDUCTOR:0:0 DIELECTRIC:0:0 THIN_DIELECTRIC:0:0 COMPENSATED:1:0
COAT_ALBEDO:1:0 THINFILM:1:0 RANDOM_WALK:1:1 HOMOGENEOUS:0:0 TRACKER:0:1 SGGX:0:0 SGGX_MAKE:0:0 FIBER:0:0 MORE_PHASE:0:0 DRAINE_MIE:0:0
GENERIC:0:0 GENERIC_ALL:1:1 MATERIALS:1:1 OPENPBR:1:1"
fail=0
printf '%-16s %5s %6s %6s %8s %6s %5s\n' family regs stack spill gmem cmem3 f64
for spec in $families; do
  IFS=: read -r f tables stack_ok <<< "$spec"
  log="$out/$f.ptxas.txt"; ptx="$out/$f.ptx"
  if ! nvcc -x cu -std=c++17 -DFAMILY_$f -Xptxas -v -c tests/gpu/kernels.cu -o "$out/$f.o" > "$log" 2>&1 ||
     ! nvcc -x cu -std=c++17 -DFAMILY_$f -ptx tests/gpu/kernels.cu -o "$ptx" >> "$log" 2>&1; then
    cat "$log"; echo "gpu footprint: $f does not compile"; fail=1; continue
  fi
  regs=$(grep -o 'Used [0-9]* registers' "$log" | awk '{m = $2 > m ? $2 : m} END {print m + 0}')
  stack=$(grep -o '[0-9]* bytes stack frame' "$log" | awk '{m = $1 > m ? $1 : m} END {print m + 0}')
  spill=$(grep -o '[0-9]* bytes spill stores' "$log" | awk '{s += $1} END {print s + 0}')
  gmem=$(grep -o '[0-9]* bytes gmem' "$log" | awk '{s += $1} END {print s + 0}')
  cmem3=$(grep -o '[0-9]* bytes cmem\[3\]' "$log" | awk '{s += $1} END {print s + 0}')
  f64=$(grep -cE '^\s+[a-z0-9_.]*\.f64\b' "$ptx")
  printf '%-16s %5s %6s %6s %8s %6s %5s\n' "$f" "$regs" "$stack" "$spill" "$gmem" "$cmem3" "$f64"
  [ "$cmem3" -eq 0 ] || { echo "  FAIL $f: $cmem3 bytes of user constant memory"; fail=1; }
  [ "$tables" -eq 1 ] || [ "$gmem" -eq 0 ] || { echo "  FAIL $f: $gmem bytes of global data without a table model"; fail=1; }
  [ "$f64" -eq 0 ] || { echo "  FAIL $f: $f64 f64 instructions"; grep -E '\.f64' "$ptx" | head -3; fail=1; }
  if [ "$stack_ok" -eq 0 ]; then
    [ "$stack" -eq 0 ] && [ "$spill" -eq 0 ] || { echo "  FAIL $f: stack $stack, spills $spill bytes"; fail=1; }
  fi
done
[ $fail -eq 0 ] && echo "gpu footprint ok: 0 B user constant memory, no f64, no spills or stack in the samplers"
exit $fail
