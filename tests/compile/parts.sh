#!/bin/sh
# tests/compile/parts.sh - the parts of appear.h that a build can compile out, read from the
# header itself, so that no list of parts is kept by hand: PART is one when a part banner
# reads "Switch: APPEAR_NO_PART" and the header has "#define APPEAR_HAS_PART 1".
#
#   sh tests/compile/parts.sh HEADER
#       prints -DAPPEAR_NO_PART for every part (make check-compile's NO_PARTS build)
#   sh tests/compile/parts.sh HEADER CC [FLAG]...
#       compiles HEADER as C with CC FLAGS (make check-compile): every part on (each
#       APPEAR_HAS_PART defined), every part off (none defined), and each part alone off
#       (its APPEAR_HAS_PART undefined, and the header still compiles); exit 1 on the first
#       disagreement
set -e
h=${1:?usage: parts.sh HEADER [CC FLAG...]}
shift
sw=$(sed -n 's/.*Switch: APPEAR_NO_\([A-Z0-9_]*\).*/\1/p' "$h" | sort -u)
has=$(sed -n 's/^#define APPEAR_HAS_\([A-Z0-9_]*\) 1.*/\1/p' "$h" | sort -u)
parts=
for p in $sw; do
    if printf '%s\n' "$has" | grep -qx "$p"; then parts="$parts $p"; fi
done
if [ -z "$parts" ]; then echo "parts.sh: no part found in $h" >&2; exit 1; fi
if [ $# -eq 0 ]; then
    for p in $parts; do printf -- '-DAPPEAR_NO_%s ' "$p"; done
    echo
    exit 0
fi

# $1: "on" (APPEAR_HAS_ of the rest must be defined) or "off"; the rest: parts
snippet() {
    want=$1; shift
    printf '#include "%s"\n' "$abs"
    for p in "$@"; do
        if [ "$want" = on ]; then
            printf '#ifndef APPEAR_HAS_%s\n#error "APPEAR_HAS_%s undefined, its part on"\n#endif\n' \
                "$p" "$p"
        else
            printf '#ifdef APPEAR_HAS_%s\n#error "APPEAR_HAS_%s defined with APPEAR_NO_%s"\n#endif\n' \
                "$p" "$p" "$p"
        fi
    done
    echo 'int appear_parts_tu;'
}
abs=$(cd "$(dirname "$h")" && pwd)/$(basename "$h")
all_off=
for p in $parts; do all_off="$all_off -DAPPEAR_NO_$p"; done
# shellcheck disable=SC2086
snippet on $parts | "$@" -x c -c - -o /dev/null
# shellcheck disable=SC2086
snippet off $parts | "$@" $all_off -x c -c - -o /dev/null
n=0
for p in $parts; do
    snippet off "$p" | "$@" -DAPPEAR_NO_"$p" -x c -c - -o /dev/null
    n=$((n + 1))
done
lone_sw=; lone_has=
for p in $sw; do case " $parts " in *" $p "*) ;; *) lone_sw="$lone_sw $p" ;; esac; done
for p in $has; do case " $parts " in *" $p "*) ;; *) lone_has="$lone_has $p" ;; esac; done
echo "compile ok: the parts of $h, all on, all off and each alone off ($n:$parts;" \
    "switch without APPEAR_HAS_:${lone_sw:- none}; APPEAR_HAS_ without a switch:${lone_has:- none})" \
    "[$*]"
