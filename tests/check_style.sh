#!/bin/sh
# tests/check_style.sh - the header's line length: at most 5% of appear.h's
# lines may exceed 100 columns, none may exceed 120 (make check-style, part
# of make test). .clang-format holds the style for new code.
f=${1:-appear.h}
awk -v f="$f" '
    { n++; if (length($0) > 100) { long++; if (length($0) > 120) { over++; if (over <= 5) printf "%s:%d: %d columns\n", f, NR, length($0) } } }
    END {
        share = n ? 100.0 * long / n : 0
        printf "check-style: %d of %d lines over 100 columns (%.1f%%, limit 5%%), %d over 120 (limit 0)\n", long, n, share, over
        exit (share > 5.0 || over > 0) ? 1 : 0
    }' "$f"
