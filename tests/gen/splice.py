#!/usr/bin/env python3
"""Replace the generated albedo tables in appear.h (from the line
/* BEGIN GENERATED ALBEDO TABLES ... through /* END GENERATED ALBEDO TABLES */)
by the file given (the output of tests/gen/gen_albedo.c):
    python3 tests/gen/splice.py build/albedo_tables.h
The block lives in the trailing generated part of the header, SECTION tables
(its banner ">>tables  SECTION tables", closed by "END SECTION tables"), before
the hand-written accessors and lookups; the splice checks that it is there."""
import sys
BEGIN, END = '/* BEGIN GENERATED ALBEDO TABLES', '/* END GENERATED ALBEDO TABLES */\n'
src = open('appear.h').read()
new = open(sys.argv[1]).read()
assert new.startswith(BEGIN) and new.endswith(END), 'not a complete gen_albedo output'
start = src.index(BEGIN)
end = src.index(END, start) + len(END)
part, part_end = src.index('>>tables  SECTION tables'), src.index('/* END SECTION tables */')
assert src.count(BEGIN) == 1 and part < start < end <= part_end, \
    'the generated block is not (only) inside SECTION tables of appear.h'
open('appear.h', 'w').write(src[:start] + new + src[end:])
